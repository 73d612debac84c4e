// <inkwire-call server="ws://HOST:PORT/ws" session="NAME">: a call as a person meets it (SPEC
// F7-F11, CONTRACTS.md). Before joining: the camera's preview, the microphone's level, a name
// and the neutral photo (taken from the preview, retaken at will). In the call: a grid of every
// member drawn from codes alone (each member's neutral photo deformed by the expression the
// server reads from their camera, or their mouth from their voice), the active speakers framed,
// names under the tiles; mute, camera off, leave. The connection and the voice live off the page's
// thread (call/voice.js: a worker with the WebSocket and WebCodecs' Opus, audio worklets that
// capture and play), the face goes as small JPEG crops the server analyses (call/camera.js). A
// member without a camera, a microphone, permission or what its engine lacks joins as a listener
// and says why (`reason`).
// Attributes: server, session, token, name, muted, camera ("off"). Sets `joined` once in the
// call; properties `members`: [{name, speaking, expression}], `voiceStats` ({played, late,
// dropped, delayMs}: what it heard) and `reason` ('' or why this engine cannot carry its voice);
// method join() does what the Join button does, leave() what Leave does; counters voiceSent and
// camera.sent say what went out.
import { kExpressionNames, parseLandmarks, parseTemplates } from '../common/face.js';
import { CameraSender, photoOf } from '../call/camera.js';
import { CallLink, voiceUnsupported } from '../call/voice.js';
import { FaceReconstructor } from '../render/face/face_reconstructor.js';
import { loadTweenShaders } from '../render/tween/tween_view.js';
import { decodeImage, SessionElement } from './session_element.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 240px; background: #1e1e22; color: #eee;
          font: 14px system-ui, sans-serif; }
  .prejoin { display: flex; flex-wrap: wrap; gap: 12px; padding: 12px; align-items: flex-start; }
  .prejoin video, .prejoin img { width: 240px; height: 180px; background: #000; object-fit: contain; border-radius: 4px; }
  .prejoin .form { display: flex; flex-direction: column; gap: 8px; min-width: 200px; }
  meter { width: 100%; }
  .grid { position: absolute; inset: 0 0 48px 0; }
  canvas { width: 100%; height: 100%; display: block; }
  .caption { position: absolute; font-size: 12px; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
  .caption.speaking { color: #5ae678; font-weight: 600; }
  .controls { position: absolute; left: 0; right: 0; bottom: 0; height: 48px; display: flex; gap: 8px; justify-content: center;
              align-items: center; }
  button { font: inherit; padding: 6px 14px; border-radius: 4px; border: 0; background: #3a3a42; color: #eee; cursor: pointer; }
  button.join, button.leave { background: #2f7a45; }
  button.leave { background: #a33; }
  .message { color: #f99; min-height: 1.2em; }
  [hidden] { display: none !important; }
</style>
<div class="prejoin" part="prejoin">
  <video class="preview" muted playsinline autoplay aria-label="your camera"></video>
  <img class="photo" alt="your neutral photo">
  <div class="form">
    <label>Microphone <meter class="level" min="-60" max="0" low="-45" value="-60"></meter></label>
    <label>Name <input class="name" maxlength="64" autocomplete="name"></label>
    <button class="take">Take photo</button>
    <button class="join">Join</button>
    <div class="message" role="status"></div>
  </div>
</div>
<div class="grid" hidden><canvas part="canvas"></canvas><div class="captions"></div></div>
<div class="controls" hidden><button class="mute">Mute</button><button class="camera">Camera off</button><button class="leave">Leave</button></div>`;

const kGap = 6, kCaption = 20;

// What a person would say of a member under its tile: listening (neither camera nor
// microphone), muted, camera off, no face found (a camera on that shows none), speaking.
export function tileState(m, speaking) {
  if (!m.camera && !m.microphone) return ', listening';
  const said = [];
  if (!m.microphone) said.push('muted');
  if (!m.camera) said.push('camera off');
  else if (!m.face_found) said.push('no face found');
  if (speaking) said.push('speaking');
  return said.length ? `, ${said.join(', ')}` : '';
}

export class InkwireCall extends SessionElement {
  static observedAttributes = [...SessionElement.observedAttributes, 'name'];

  constructor() {
    super(template);
    const $ = (s) => this.shadowRoot.querySelector(s);
    Object.assign(this, { preview: $('.preview'), photoImg: $('.photo'), level: $('.level'), nameInput: $('.name'), prejoin: $('.prejoin'),
                          grid: $('.grid'), captions: $('.captions'), controls: $('.controls'), muteButton: $('.mute'), cameraButton: $('.camera') });
    $('.take').addEventListener('click', () => this.takePhoto());
    $('.join').addEventListener('click', () => this.join());
    $('.leave').addEventListener('click', () => this.leave());
    this.muteButton.addEventListener('click', () => this.setMuted(!this.muted));
    this.cameraButton.addEventListener('click', () => this.setCameraOff(!this.cameraOff));
    this.faces = new Map();  // member -> {face, expression}
    this.roster = { you: 0, members: [] };
  }

  get voiceStats() { return this.link?.voiceStats ?? { played: 0, late: 0, dropped: 0, delayMs: 0 }; }
  get voiceSent() { return this.link?.status.voiceSent ?? 0; }

  get members() {
    return this.roster.members.map((m) => ({ name: m.name, speaking: m.speaking, expression: kExpressionNames[this.faces.get(m.member)?.code ?? 0] }));
  }

  // Pre-join: the camera and microphone (or the reason there are none).
  async start() {
    this.leave();
    this.nameInput.value = this.getAttribute('name') ?? this.nameInput.value;
    this.muted = this.hasAttribute('muted');
    this.cameraOff = this.getAttribute('camera') === 'off';
    this.reason = voiceUnsupported();
    this.hasVoice = false;
    this.link?.close();
    // The worker and the audio graph are made while the person is in pre-join.
    const link = (this.link = new CallLink({ onLevel: (db) => (this.level.value = db) }));
    try {
      this.media = await navigator.mediaDevices.getUserMedia({ video: !this.cameraOff, audio: !this.reason });
    } catch (error) {
      this.media = null;
      this.reason ||= `no camera or microphone (${error.message}): you will join as a listener`;
    }
    const video = this.media?.getVideoTracks()[0], audio = this.media?.getAudioTracks()[0];
    if (video) this.preview.srcObject = new MediaStream([video]);
    this.preview.hidden = !video;
    this.reason ||= await link.reason;
    if (audio && !this.reason) {
      try {
        await link.capture(audio);
        this.hasVoice = true;
        // The microphone may come after a quick Join: the call hears of it now.
        if (this.hasAttribute('joined')) this.publish();
      } catch (error) {
        this.reason = `${error.message}: you will join without voice`;
      }
    }
    if (this.reason) this.message.textContent = this.reason;
  }

  async takePhoto() {
    if (!this.preview.videoWidth) return;
    this.photo = await photoOf(this.preview);
    this.photoImg.src = URL.createObjectURL(new Blob([this.photo], { type: 'image/jpeg' }));
    if (this.session && this.hasAttribute('joined')) this.session.send({ type: 'neutral-photo', jpeg: this.photo });
  }

  now() { return this.link.now(); }

  join() {
    if (this.session) return;
    const server = this.getAttribute('server') ?? `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`;
    const name = this.nameInput.value.trim() || this.getAttribute('name') || 'guest';
    const session = (this.session = this.link.open(server, this.getAttribute('session') ?? '', this.getAttribute('token') ?? '', name.slice(0, 64)));
    session.addEventListener('error', (e) => this.fail(e.detail));
    session.addEventListener('refused', (e) => this.refused(e.detail));
    session.addEventListener('snapshot', () => this.entered(session), { once: true });
    session.addEventListener('roster', (e) => this.updateRoster(session, e.detail));
    session.addEventListener('face-region', (e) => { if (this.camera) this.camera.region = e.detail; });
    session.addEventListener('member-face', (e) => this.faceArrived(e.detail));
    session.addEventListener('close', () => { if (this.session === session) this.leave(); });
  }

  async entered(session) {
    if (this.preview.videoWidth && !this.photo) await this.takePhoto();
    if (this.session !== session) return;
    if (this.photo) session.send({ type: 'neutral-photo', jpeg: this.photo });
    if (this.preview.videoWidth) this.camera = new CameraSender(this.preview, (m) => this.session?.send(m), () => this.now());
    if (this.camera) this.camera.off = this.cameraOff;
    this.publish();
    this.prejoin.hidden = true;
    this.grid.hidden = this.controls.hidden = false;
    this.setAttribute('joined', '');
    this.dispatchEvent(new Event('joined'));
    this.loop();
  }

  // What goes out, said to the call and done: voice flows only while it says a microphone is on.
  publish() {
    const microphone = !!this.hasVoice && !this.muted;
    if (this.link) this.link.sending = microphone && !!this.session;
    this.session?.send({ type: 'publish', camera: !!this.camera && !this.cameraOff, microphone });
    this.muteButton.textContent = this.muted ? 'Unmute' : 'Mute';
    this.cameraButton.textContent = this.cameraOff ? 'Camera on' : 'Camera off';
    this.muteButton.disabled = !this.hasVoice;
    this.cameraButton.disabled = !this.camera;
  }

  setMuted(muted) {
    this.muted = muted;
    this.publish();
  }

  setCameraOff(off) {
    this.cameraOff = off;
    if (this.camera) this.camera.off = off;
    this.publish();
  }

  leave() {
    this.session?.close();  // says leave first, in the worker
    this.session = null;
    if (this.link) this.link.sending = false;
    this.camera?.stop();
    this.camera = null;
    this.faces.clear();
    this.roster = { you: 0, members: [] };
    this.captions.textContent = '';
    if (this.hasAttribute('joined')) this.removeAttribute('joined');
    this.prejoin.hidden = false;
    this.grid.hidden = this.controls.hidden = true;
  }

  disconnectedCallback() {
    this.leave();
    this.link?.close();
    this.link = null;
    this.hasVoice = false;
    for (const track of this.media?.getTracks() ?? []) track.stop();
    super.disconnectedCallback();
  }

  async updateRoster(session, roster) {
    this.roster = roster;
    const mine = roster.members.find((m) => m.member === roster.you);
    if (mine && !mine.face_found && mine.camera) this.message.textContent = 'no face found in your camera picture';
    for (const m of roster.members) {
      const known = this.faces.get(m.member);
      if (m.assets.length !== 2 || (known && known.photo === m.assets[0].hash.join())) continue;
      this.faces.set(m.member, { ...(known ?? { code: 0 }), photo: m.assets[0].hash.join(), loading: true });
      try {
        const [image, landmarks, templates, shaders] = await Promise.all([
          session.fetchAsset(m.assets[0]).then(decodeImage),
          session.fetchAsset(m.assets[1]).then((b) => parseLandmarks(JSON.parse(new TextDecoder().decode(b)))),
          this.templates ??= fetch(new URL('../face/expression_templates.json', import.meta.url)).then((r) => r.json()).then(parseTemplates),
          this.shaders ??= loadTweenShaders(),
        ]);
        if (this.session !== session) return;
        const face = new FaceReconstructor(this.webgl(), image.data, image.width, image.height, landmarks, templates, shaders);
        const entry = this.faces.get(m.member);
        face.setExpression(entry.code, entry.intensity ?? 0, performance.now() / 1000);
        Object.assign(entry, { face, loading: false });
      } catch (error) {
        this.message.textContent = `cannot show ${m.name}: ${error.message}`;
      }
    }
    for (const member of this.faces.keys()) if (!roster.members.some((m) => m.member === member)) this.faces.delete(member);
  }

  // A face comes when the sound of its moment plays, so the mouth moves with the voice.
  faceArrived(m) {
    const due = this.link?.localTime(m.member, m.time_ms);
    const show = () => {
      const entry = this.faces.get(m.member) ?? this.faces.set(m.member, { code: 0 }).get(m.member);
      if (m.expression.code >= kExpressionNames.length) return;
      entry.code = m.expression.code;
      entry.intensity = m.expression.intensity;
      entry.face?.setExpression(entry.code, entry.intensity, performance.now() / 1000);
    };
    if (due && due > performance.now()) setTimeout(show, due - performance.now());
    else show();
  }

  loop() {
    if (!this.hasAttribute('joined')) return;
    this.draw();
    requestAnimationFrame(() => this.loop());
  }

  draw() {
    if (!this.hasAttribute('joined')) return;
    const gl = this.webgl();
    const [width, height] = this.beginFrame();
    gl.clearColor(0.12, 0.12, 0.14, 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    const tiles = this.roster.members, n = tiles.length, ratio = window.devicePixelRatio || 1;
    if (!n) return;
    let cols = 1, best = 0;
    for (let c = 1; c <= n; ++c) {
      const rows = Math.ceil(n / c), w = (width - kGap * (c + 1)) / c, h = (height - (kGap + kCaption * ratio) * rows - kGap) / rows;
      const side = Math.min(w, (h * 4) / 3);
      if (side > best) best = side, cols = c;
    }
    const rows = Math.ceil(n / cols), w = Math.floor((width - kGap * (cols + 1)) / cols);
    const h = Math.floor((height - (kGap + kCaption * ratio) * rows - kGap) / rows);
    const captions = [];
    gl.enable(gl.SCISSOR_TEST);
    tiles.forEach((m, i) => {
      const x = kGap + (i % cols) * (w + kGap), top = kGap + Math.floor(i / cols) * (h + kGap + kCaption * ratio), y = height - top - h;
      // Green follows the voice alone: only a member with a live microphone can be speaking.
      const speaking = m.speaking && m.microphone, frame = speaking ? 4 : 1;
      gl.scissor(x - frame, y - frame, w + 2 * frame, h + 2 * frame);
      gl.clearColor(...(speaking ? [0.2, 0.75, 0.35, 1] : [0.35, 0.35, 0.38, 1]));
      gl.clear(gl.COLOR_BUFFER_BIT);
      gl.scissor(x, y, w, h);
      gl.clearColor(0.12, 0.12, 0.14, 1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      const face = this.faces.get(m.member)?.face;
      if (face) {
        const scale = Math.min(w / face.width, h / face.height), fw = Math.round(face.width * scale), fh = Math.round(face.height * scale);
        face.draw(performance.now() / 1000, [width, height], [x + Math.trunc((w - fw) / 2), y + Math.trunc((h - fh) / 2), fw, fh]);
      }
      captions.push({ text: `${m.name}${m.member === this.roster.you ? ' (you)' : ''}${tileState(m, speaking)}`, speaking,
                      left: x / ratio, top: (top + h + 2) / ratio, width: w / ratio });
    });
    gl.disable(gl.SCISSOR_TEST);
    // Names as text the page can read, under their tiles.
    const text = JSON.stringify(captions);
    if (text !== this.shownCaptions) {
      this.shownCaptions = text;
      this.captions.replaceChildren(...captions.map((c) => {
        const div = document.createElement('div');
        div.className = `caption${c.speaking ? ' speaking' : ''}`;
        Object.assign(div.style, { left: `${c.left}px`, top: `${c.top}px`, width: `${c.width}px` });
        div.textContent = c.text;
        return div;
      }));
    }
  }
}

if (!customElements.get('inkwire-call')) customElements.define('inkwire-call', InkwireCall);
