// <inkwire-call server="ws://HOST:PORT/ws" session="NAME">: a call as a person meets it (SPEC
// F7-F11, F15-F16, CONTRACTS.md). Before joining: the camera's preview, the microphone's level, a
// name and the neutral photo (taken from the preview, retaken at will); the renderer loads
// meanwhile. In the call: a grid of every member drawn from codes alone by the native C++ in the
// session's style (elements/call/tiles.js: each member's neutral photo deformed by the expression
// the server reads from their camera, or their mouth from their voice), the active speakers
// framed, captions under the tiles; mute, camera off, leave. The connection and the voice live off
// the page's thread (call/voice.js: a worker with the WebSocket and WebCodecs' Opus, audio
// worklets that capture and play), the face goes as small JPEG crops the server analyses
// (call/camera.js). A member without a camera, a microphone, permission or what its engine lacks
// joins as a listener and says why (`reason`).
// Attributes: server, session, token, name, muted, camera ("off"). Sets `joined` once in the
// call; properties `members`: [{name, speaking, expression}], `voiceStats` ({played, late,
// dropped, delayMs}: what it heard) and `reason` ('' or why this engine cannot carry its voice);
// method join() does what the Join button does, hangUp() what Leave does (a lost connection is
// joined again, under the same name, until then); counters voiceSent and
// camera.sent say what went out; `joinedAt` and `firstFaceAt` (performance.now() of joining and
// of the first frame with a face).
import { CameraSender, faceFormat, photoOf } from '../call/camera.js';
import { CallLink, voiceUnsupported } from '../call/voice.js';
import { CallTiles } from './call/tiles.js';
import { SessionElement } from './session_element.js';

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

export class InkwireCall extends SessionElement {
  static observedAttributes = [...SessionElement.observedAttributes, 'name'];

  constructor() {
    super(template);
    const $ = (s) => this.shadowRoot.querySelector(s);
    Object.assign(this, { preview: $('.preview'), photoImg: $('.photo'), level: $('.level'), nameInput: $('.name'), prejoin: $('.prejoin'),
                          grid: $('.grid'), controls: $('.controls'), muteButton: $('.mute'), cameraButton: $('.camera') });
    $('.take').addEventListener('click', () => this.takePhoto());
    $('.join').addEventListener('click', () => this.join());
    $('.leave').addEventListener('click', () => this.hangUp());
    this.muteButton.addEventListener('click', () => this.setMuted(!this.muted));
    this.cameraButton.addEventListener('click', () => this.setCameraOff(!this.cameraOff));
    this.tiles = new CallTiles(this.canvas, $('.captions'));
    this.photos = new Map();  // member -> the hash of the photo its tile shows
    this.expressions = new Map();  // member -> the expression ({code, intensity}) last due
    this.roster = { you: 0, members: [] };
  }

  get voiceStats() { return this.link?.voiceStats ?? { played: 0, late: 0, dropped: 0, delayMs: 0 }; }
  get voiceSent() { return this.link?.status.voiceSent ?? 0; }

  get members() {
    const names = this.tiles.names ?? [];
    return this.roster.members.map((m) => ({ name: m.name, speaking: m.speaking, expression: names[this.expressions.get(m.member)?.code ?? 0] ?? 'neutral' }));
  }

  // Pre-join: the camera and microphone (or the reason there are none), and the renderer.
  async start() {
    this.leave();
    this.nameInput.value = this.getAttribute('name') ?? this.nameInput.value;
    this.muted = this.hasAttribute('muted');
    this.cameraOff = this.getAttribute('camera') === 'off';
    this.reason = voiceUnsupported();
    this.hasVoice = false;
    this.tilesReady ??= this.tiles.load(this.serverUrl());
    this.tilesReady.catch((error) => this.fail(`faces cannot be drawn: ${error.message}`));
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
    const name = this.nameInput.value.trim() || this.getAttribute('name') || 'guest';
    const session = (this.session = this.link.open(this.serverUrl(), this.getAttribute('session') ?? '', this.joinToken(), name.slice(0, 64)));
    session.addEventListener('error', (e) => this.fail(e.detail));
    session.addEventListener('refused', (e) => this.refused(e.detail));
    session.addEventListener('snapshot', (e) => this.entered(session, e.detail), { once: true });
    session.addEventListener('state', (e) => { if (e.detail.type === 'style-change') this.showStyle(e.detail); });
    session.addEventListener('roster', (e) => this.updateRoster(session, e.detail));
    session.addEventListener('face-region', (e) => { if (this.camera) this.camera.region = e.detail; });
    session.addEventListener('key-frame-request', () => this.camera?.keyFrame());
    session.addEventListener('member-face', (e) => this.faceArrived(e.detail));
    session.addEventListener('close', () => this.lost(session));
  }

  // A connection lost while in the call (Wi-Fi, a laptop lid, a server gone quiet: SPEC F19) is
  // joined again under the same name, every 2 s for a minute; the server gives the member its
  // tile back. Leaving on purpose (hangUp) stops that.
  lost(session) {
    if (this.session !== session) return;
    if (this.hasAttribute('joined')) this.rejoinUntil = performance.now() + 60000;
    this.leave();
    if (!(performance.now() < this.rejoinUntil) || !this.isConnected) return;
    this.message.textContent = 'the connection was lost: joining again';
    setTimeout(() => { if (!this.session && this.isConnected && performance.now() < this.rejoinUntil) this.join(); }, 2000);
  }

  // The Leave button: out of the call, and no joining again.
  hangUp() {
    this.rejoinUntil = 0;
    this.leave();
  }

  async entered(session, snapshot) {
    if (this.rejoinUntil) this.message.textContent = '';
    this.rejoinUntil = 0;
    if (this.preview.videoWidth && !this.photo) await this.takePhoto();
    const format = await faceFormat();
    if (this.session !== session) return;
    if (this.photo) session.send({ type: 'neutral-photo', jpeg: this.photo });
    if (this.preview.videoWidth) this.camera = new CameraSender(this.preview, (m) => this.session?.send(m), () => this.now(), format);
    if (this.camera) this.camera.off = this.cameraOff;
    this.publish();
    this.prejoin.hidden = true;
    this.grid.hidden = this.controls.hidden = false;
    this.joinedAt ??= performance.now();
    this.setAttribute('joined', '');
    this.dispatchEvent(new Event('joined'));
    this.showStyle(snapshot.style);
    this.loop();
  }

  // The session's style on every tile, once the renderer is there.
  async showStyle(style) {
    await this.tilesReady;
    const reason = this.tiles.setStyle(style);
    if (reason) this.message.textContent = `the faces keep their look: ${reason}`;
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
    this.photos.clear();
    this.expressions.clear();
    this.roster = { you: 0, members: [] };
    if (this.tiles.view) this.tiles.setRoster(this.roster);
    if (this.hasAttribute('joined')) this.removeAttribute('joined');
    this.prejoin.hidden = false;
    this.grid.hidden = this.controls.hidden = true;
  }

  disconnectedCallback() {
    this.hangUp();
    this.link?.close();
    this.link = null;
    this.hasVoice = false;
    for (const track of this.media?.getTracks() ?? []) track.stop();
    super.disconnectedCallback();
  }

  // The roster on the tiles at once; each new photo (and its landmarks) handed to the renderer
  // as it arrives, the roster then given again so its tile shows the face.
  async updateRoster(session, roster) {
    this.roster = roster;
    const mine = roster.members.find((m) => m.member === roster.you);
    if (mine && !mine.face_found && mine.camera) this.message.textContent = 'no face found in your camera picture';
    await this.tilesReady;
    if (this.session !== session) return;
    this.tiles.setRoster(this.roster);
    for (const member of this.photos.keys()) if (!roster.members.some((m) => m.member === member)) this.photos.delete(member);
    for (const m of roster.members) {
      const photo = m.assets[0]?.hash.join();
      if (m.assets.length !== 2 || this.photos.get(m.member) === photo) continue;
      this.photos.set(m.member, photo);
      try {
        const [bytes, landmarks] = await Promise.all([session.fetchAsset(m.assets[0]), session.fetchAsset(m.assets[1])]);
        if (this.session !== session || this.photos.get(m.member) !== photo) continue;
        this.tiles.setMemberFace(m.member, bytes, new TextDecoder().decode(landmarks));
        this.tiles.setRoster(this.roster);
        const expression = this.expressions.get(m.member);
        if (expression) this.tiles.setFace(m.member, expression);
      } catch (error) {
        this.message.textContent = `cannot show ${m.name}: ${error.message}`;
      }
    }
  }

  // A face comes when the sound of its moment plays, so the mouth moves with the voice.
  faceArrived(m) {
    const due = this.link?.localTime(m.member, m.time_ms);
    const show = () => {
      if (!this.session) return;
      this.expressions.set(m.member, m.expression);
      if (this.tiles.view) this.tiles.setFace(m.member, m.expression);
    };
    if (due && due > performance.now()) setTimeout(show, due - performance.now());
    else show();
  }

  loop() {
    if (!this.hasAttribute('joined')) return;
    if (this.tiles.view && this.tiles.due()) {
      try {
        if (this.tiles.draw(performance.now() / 1000)) this.firstFaceAt ??= performance.now();
      } catch (error) {
        this.fail(`the call cannot be drawn: ${error.message}`);
        return;
      }
    }
    requestAnimationFrame(() => this.loop());
  }
}

if (!customElements.get('inkwire-call')) customElements.define('inkwire-call', InkwireCall);
