// A scene's page (server/web/pages.cpp): its element full-size, and for its editor (this
// browser holds the scene's editor key: given by the upload that made it, kept in localStorage,
// or in the address as #editor=KEY) the link to share and "Replace the model", which uploads a
// new model into the running scene: every member gets it, its style and camera kept.
import { editorKeyStorage, pageServerUrl, takeFiles, uploadModel } from './upload.js';

const element = document.querySelector('inkwire-scene');
const scene = element.getAttribute('session');
const storage = editorKeyStorage(pageServerUrl(), scene);
const fromAddress = new URLSearchParams(location.hash.slice(1)).get('editor');
if (fromAddress) {
  try {
    localStorage.setItem(storage, fromAddress);
  } catch {}
  history.replaceState(null, '', location.pathname);
}
let key = fromAddress;
try {
  key ||= localStorage.getItem(storage);
} catch {}
const form = document.querySelector('form.replace');
if (key) {
  element.setAttribute('editor-token', key);
  form.hidden = false;
  takeFiles(form, async (files) => {
    const status = form.querySelector('.status'), progress = form.querySelector('progress');
    progress.hidden = false;
    status.textContent = 'Uploading...';
    try {
      const { status: code, answer } = await uploadModel(files, {
        url: `/scenes/${encodeURIComponent(scene)}/model`, headers: { 'X-Inkwire-Editor-Key': key }, onProgress: (share) => (progress.value = share),
      });
      if (code !== 200) throw new Error(answer.error);
      status.textContent = `Replaced: ${answer.triangles} triangles, everyone sees it now.`;
    } catch (error) {
      status.textContent = `Refused: ${error.message}`;
    }
    progress.hidden = true;
  });
}
