// The server's front page (server/web/pages.cpp): "New scene" uploads the model a visitor picks
// or drops (every file of it: a glTF with its .bin and images, an OBJ with its .mtl and textures)
// with a progress bar; the server answers with the scene's page and the key that makes its
// maker the editor, which this browser keeps for that scene (as <inkwire-scene> reads it) before
// going there. A refusal is said in one line.
import { editorKeyStorage, pageServerUrl, takeFiles, uploadModel } from './upload.js';

const form = document.querySelector('form.upload');

async function newScene(files) {
  const status = form.querySelector('.status'), progress = form.querySelector('progress');
  if (!files.length) return;
  progress.hidden = false;
  progress.value = 0;
  status.textContent = `Uploading ${files.length === 1 ? files[0].name : `${files.length} files`}...`;
  try {
    const { status: code, answer } = await uploadModel(files, {
      url: '/scenes',
      headers: { 'X-Inkwire-Creator-Token': form.querySelector('input[name=token]')?.value },
      onProgress: (share) => {
        progress.value = share;
        if (share >= 1) status.textContent = 'Making the scene...';
      },
    });
    if (code !== 201) throw new Error(answer.error);
    try {
      localStorage.setItem(editorKeyStorage(pageServerUrl(), answer.name), answer.editor_key);
    } catch {
      // no storage here: the page's address carries the key instead
    }
    location.href = `${answer.page}#editor=${answer.editor_key}`;
  } catch (error) {
    progress.hidden = true;
    status.textContent = `Refused: ${error.message}`;
  }
}

if (form) takeFiles(form, newScene);
