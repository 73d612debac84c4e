// <inkwire-call server="ws://HOST:PORT/ws" session="NAME">: a call as a person meets it (SPEC
// F7-F11, F15-F16, docs/calls.md). Before joining: the camera's preview, the microphone's level, a
// name and the neutral photo (taken from the preview, retaken at will); the renderer loads
// meanwhile. In the call: a grid of every member drawn from codes alone by the native C++ in the
// session's style (elements/call/tiles.js: each member's neutral photo deformed by the expression
// the server reads from their camera, or their mouth from their voice), the active speakers
// framed, captions under the tiles; mute, camera off, leave. The connection and the voice live off
// the page's thread (call/voice.js: a worker with the WebSocket and WebCodecs' Opus, audio
// worklets that capture and play), the face goes as VP8 video (JPEG crops where an engine has no
// encoder) the server analyses (call/camera.js). One feature a file: elements/call/
// prejoin.js, membership.js, publishing.js, faces.js and tiles.js. A member without a camera, a microphone, permission or what its engine lacks
// joins as a listener and says why (`reason`).
// Attributes: server, session, token, name, muted, camera ("off"), open-room (open a call room of
// that name when there is none; its opener is its host: elements/call/hosting.js). Sets `joined`
// once in the call; properties `isHost`, `locked`, `members`: [{name, speaking, expression}], `voiceStats` ({played, late,
// dropped, delayMs, skipped}: what it heard) and `reason` ('' or why this engine cannot carry its voice);
// method join() does what the Join button does, hangUp() what Leave does (a lost connection is
// joined again, under the same name, until then); counters voiceSent and
// camera.sent say what went out; `joinedAt` and `firstFaceAt` (performance.now() of joining and
// of the first frame with a face).
import { FacesMixin } from './call/faces.js';
import { HostingMixin } from './call/hosting.js';
import { MembershipMixin } from './call/membership.js';
import { PrejoinMixin } from './call/prejoin.js';
import { PublishingMixin } from './call/publishing.js';
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
  .caption .remove { padding: 0 6px; margin-right: 4px; background: #a33; font-size: 12px; line-height: 16px; }
  .lock-note { color: #f7c46c; font-size: 12px; }
  select { font: inherit; padding: 5px; border-radius: 4px; background: #3a3a42; color: #eee; border: 0; }
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
<div class="controls" hidden><button class="mute">Mute</button><button class="camera">Camera off</button>
  <button class="lock" hidden>Lock room</button>
  <select class="style" hidden aria-label="The call's style"><option value="default">Plain</option><option value="comic-extended">Comic</option>
    <option value="painterly">Painted</option></select>
  <span class="lock-note"></span><button class="leave">Leave</button></div>`;

export class InkwireCall extends HostingMixin(FacesMixin(PublishingMixin(MembershipMixin(PrejoinMixin(SessionElement))))) {
  static observedAttributes = [...SessionElement.observedAttributes, 'name'];

  constructor() {
    super(template);
    const $ = (s) => this.shadowRoot.querySelector(s);
    Object.assign(this, { preview: $('.preview'), photoImg: $('.photo'), level: $('.level'), nameInput: $('.name'), prejoin: $('.prejoin'),
                          grid: $('.grid'), controls: $('.controls'), muteButton: $('.mute'), cameraButton: $('.camera'),
                          lockButton: $('.lock'), styleSelect: $('.style'), lockNote: $('.lock-note') });
    $('.take').addEventListener('click', () => this.takePhoto());
    $('.join').addEventListener('click', () => this.join());
    $('.leave').addEventListener('click', () => this.hangUp());
    this.muteButton.addEventListener('click', () => this.setMuted(!this.muted));
    this.cameraButton.addEventListener('click', () => this.setCameraOff(!this.cameraOff));
    this.lockButton.addEventListener('click', () => this.lockRoom(!this.locked));
    this.styleSelect.addEventListener('change', () => this.setCallStyle(this.styleSelect.value));
    this.captionDecorator = (div, tile) => this.decorateCaption(div, tile);
    this.tiles = new CallTiles(this.canvas, $('.captions'));
    this.photos = new Map();  // member -> the hash of the photo its tile shows
    this.expressions = new Map();  // member -> its face (member-layers or member-face) last due
    this.roster = { you: 0, members: [] };
  }

  get voiceStats() { return this.link?.voiceStats ?? { played: 0, late: 0, dropped: 0, delayMs: 0, skipped: 0 }; }
  get voiceSent() { return this.link?.status.voiceSent ?? 0; }
  // How the voice passes between the worker and the audio worklets: 'rings' (shared memory, on a
  // cross-origin isolated page) or 'ports' (message ports, elsewhere: `isolationNote` says so).
  get voicePath() { return this.link?.shared ? 'rings' : 'ports'; }

  get members() {
    const names = this.tiles.names ?? [];
    // What a member's tile shows; before its photo is in, what its last face said.
    const shown = (member) => (this.tiles.view && this.tiles.expressionOf(member)) || names[this.expressions.get(member)?.expression.code ?? 0] || 'neutral';
    return this.roster.members.map((m) => ({ name: m.name, speaking: m.speaking, expression: shown(m.member), face: this.tiles.view ? this.tiles.faceOf(m.member) : null }));
  }

  now() { return this.link.now(); }

  // The grid is drawn by the call's own loop (faces.js) whenever something changed; a new size
  // (SessionElement's observer asks for this) is such a change.
  redraw() { this.tiles.changed = true; }

  disconnectedCallback() {
    this.hangUp();
    this.link?.close();
    this.link = null;
    this.hasVoice = false;
    for (const track of this.media?.getTracks() ?? []) track.stop();
    super.disconnectedCallback();
  }
}

if (!customElements.get('inkwire-call')) customElements.define('inkwire-call', InkwireCall);
