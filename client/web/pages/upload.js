// A model's files sent to the server as one multipart upload (server/web/uploads.hpp), with its
// progress: what the front page's "New scene" and a scene page's "Replace the model" share.
// Resolves with the server's JSON answer and status; a refusal's answer is {error}.

// Where <inkwire-scene> finds the editor key of `scene` on the server at `server` (a ws:// URL).
export const editorKeyStorage = (server, scene) => `inkwire-editor-key ${server} ${scene}`;
export const pageServerUrl = () => `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`;

export function uploadModel(files, { url, headers = {}, onProgress = () => {} }) {
  return new Promise((resolve, reject) => {
    const data = new FormData();
    for (const file of files) data.append('file', file, file.name);
    const request = new XMLHttpRequest();
    request.open('POST', url);
    for (const [name, value] of Object.entries(headers)) if (value) request.setRequestHeader(name, value);
    request.upload.onprogress = (e) => { if (e.lengthComputable) onProgress(e.loaded / e.total); };
    request.onerror = () => reject(new Error('the server could not be reached'));
    request.onload = () => {
      let answer;
      try {
        answer = JSON.parse(request.responseText);
      } catch {
        answer = { error: request.responseText.trim() || `the server answered ${request.status}` };
      }
      resolve({ status: request.status, answer });
    };
    request.send(data);
  });
}

// A form with a file input (and a drop zone `.drop`): `send(files)` for what is picked or dropped.
export function takeFiles(form, send) {
  const input = form.querySelector('input[type=file]'), drop = form.querySelector('.drop');
  input.addEventListener('change', () => send([...input.files]));
  drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
  drop.addEventListener('dragleave', () => drop.classList.remove('over'));
  drop.addEventListener('drop', (e) => {
    e.preventDefault();
    drop.classList.remove('over');
    send([...e.dataTransfer.files]);
  });
}
