// <inkwire-conference server="ws://HOST:PORT/ws" session="NAME">: a viewer of a conference
// session (SPEC W3, F16): the speaker's neutral photo and its landmarks once, then expression codes
// only (8 bytes each), the photo deformed by each code's template and drawn in the session's style
// by the native C++ (ConferenceView, compiled into the module: client/web/module/face_module.cpp),
// as the native client draws it. Sized by its container at the device pixel ratio; the photo
// fitted and centred. Property `expression` ({code, name, intensity}); attribute `loaded` once the
// face is drawn.
import { AssetKind } from '../net/session.js';
import { fitCanvas, lendBytes, loadRenderModule, SessionElement } from './session_element.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 120px; background: #fff; }
  canvas { width: 100%; height: 100%; display: block; }
  .message { position: absolute; inset: auto 8px 8px 8px; font: 13px system-ui, sans-serif; color: #a33; text-align: center; }
</style>
<canvas part="canvas"></canvas><div class="message" role="status"></div>`;

export class InkwireConference extends SessionElement {
  constructor() { super(template); }

  get expression() { return this.view ? JSON.parse(this.view.expressionJson()) : null; }

  connectedCallback() {
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', `${this.getAttribute('session') ?? 'Conference'}: the speaker's face`);
    super.connectedCallback();
  }

  start() {
    this.removeAttribute('loaded');
    this.faceShown = false;
    const session = this.openSession();
    const module = (this.moduleReady ??= loadRenderModule(this.serverUrl(), this.canvas).then(({ module }) => {
      this.view = new module.FaceView('!canvas');
      const reason = this.view.error();
      if (reason) throw new Error(reason);
      return module;
    }));
    module.catch((error) => this.fail(error.message));
    let pending = null;  // a code that came before the face
    session.addEventListener('state', async (e) => {
      if (e.detail.type === 'style-change') {
        await module;
        this.showStyle(e.detail);
      } else if (e.detail.type === 'expression-code') {
        if (this.faceShown) this.show(e.detail);
        else pending = e.detail;
      }
    });
    session.addEventListener('snapshot', async (e) => {
      try {
        const snapshot = e.detail;
        const photo = snapshot.assets.find((a) => a.kind === AssetKind.image), marks = snapshot.assets.find((a) => a.kind === AssetKind.landmarks);
        if (!photo || !marks) throw new Error('the conference has no speaker yet (no photo and landmarks)');
        const [bytes, landmarks, loaded] = await Promise.all([session.fetchAsset(photo), session.fetchAsset(marks), module]);
        if (this.session !== session) return;
        const reason = lendBytes(loaded, bytes, (address, size) => this.view.setFace(address, size, new TextDecoder().decode(landmarks)));
        if (reason) throw new Error(reason);
        this.showStyle(snapshot.style);
        this.faceShown = true;
        this.show(pending ?? snapshot.expression);
        this.setAttribute('loaded', '');
        this.dispatchEvent(new Event('load'));
      } catch (error) {
        if (this.session === session) this.fail(error.message);
      }
    });
  }

  showStyle(style) {
    const reason = this.view.setStyle(style.renderer, JSON.stringify(style.settings ?? []));
    if (reason) this.message.textContent = `the face keeps its look: ${reason}`;
    this.redraw();
  }

  // A code this version does not know is ignored by the module, as the C++ client ignores it.
  show(code) {
    this.view.setExpression(code.code, code.intensity);
    this.tweenUntil = performance.now() + 250;  // the face tweens for 100 ms
    this.redraw();
  }

  animating() { return !!this.view && (this.view.animates() || performance.now() < this.tweenUntil); }

  draw(now = performance.now() / 1000) {
    if (!this.view || !this.faceShown) return;
    fitCanvas(this.canvas);
    const reason = this.view.draw(now);
    if (reason) this.fail(reason);
  }
}

if (!customElements.get('inkwire-conference')) customElements.define('inkwire-conference', InkwireConference);
