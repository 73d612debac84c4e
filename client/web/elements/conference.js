// <inkwire-conference server="ws://HOST:PORT/ws" session="NAME">: a viewer of a conference
// session (SPEC W3): the speaker's neutral photo and its landmarks once, then expression codes
// only (8 bytes each), the photo deformed by each code's template as the C++ client deforms it
// (render/face/face_reconstructor.js). Sized by its container at the device pixel ratio; the
// photo fitted and centred. Property `expression` ({code, intensity}); attribute `loaded` once
// the photo is there.
import { parseLandmarks, parseTemplates, kExpressionNames } from '../common/face.js';
import { AssetKind } from '../net/session.js';
import { FaceReconstructor } from '../render/face/face_reconstructor.js';
import { loadTweenShaders } from '../render/tween/tween_view.js';
import { decodeImage, SessionElement } from './session_element.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 120px; background: #fff; }
  canvas { width: 100%; height: 100%; display: block; }
  .message { position: absolute; inset: auto 8px 8px 8px; font: 13px system-ui, sans-serif; color: #a33; text-align: center; }
</style>
<canvas part="canvas"></canvas><div class="message" role="status"></div>`;

export class InkwireConference extends SessionElement {
  constructor() { super(template); }

  get expression() { return this.face ? { code: this.face.code, intensity: this.face.intensity, name: kExpressionNames[this.face.code] } : null; }

  connectedCallback() {
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', `${this.getAttribute('session') ?? 'Conference'}: the speaker's face`);
    super.connectedCallback();
  }

  start() {
    this.face = null;
    this.removeAttribute('loaded');
    const session = this.openSession();
    let pending = null;  // a code that came before the photo
    session.addEventListener('state', (e) => {
      if (e.detail.type !== 'expression-code') return;
      if (this.face) this.show(e.detail);
      else pending = e.detail;
    });
    session.addEventListener('snapshot', async (e) => {
      try {
        const snapshot = e.detail;
        const photo = snapshot.assets.find((a) => a.kind === AssetKind.image), marks = snapshot.assets.find((a) => a.kind === AssetKind.landmarks);
        if (!photo || !marks) throw new Error('the conference has no speaker yet (no photo and landmarks)');
        const [image, landmarks, templates, shaders] = await Promise.all([
          session.fetchAsset(photo).then(decodeImage),
          session.fetchAsset(marks).then((b) => parseLandmarks(JSON.parse(new TextDecoder().decode(b)))),
          fetch(new URL('../face/expression_templates.json', import.meta.url)).then((r) => r.json()).then(parseTemplates),
          loadTweenShaders(),
        ]);
        if (this.session !== session) return;
        this.face = new FaceReconstructor(this.webgl(), image.data, image.width, image.height, landmarks, templates, shaders);
        this.show(pending ?? snapshot.expression);
        this.setAttribute('loaded', '');
        this.dispatchEvent(new Event('load'));
      } catch (error) {
        if (this.session === session) this.fail(error.message);
      }
    });
  }

  // A code this version does not know is ignored, as the C++ client ignores it.
  show(code) {
    if (code.code >= kExpressionNames.length) return;
    this.face.setExpression(code.code, code.intensity, performance.now() / 1000);
    this.redraw();
  }

  animating() { return this.face && !this.face.settled(performance.now() / 1000); }  // until the tween settles

  draw(now = performance.now() / 1000) {
    const face = this.face;
    if (!this.gl || !face) return;
    const [width, height] = this.beginFrame();
    const scale = Math.min(width / face.width, height / face.height);
    const w = Math.round(face.width * scale), h = Math.round(face.height * scale);
    face.draw(now, [width, height], [Math.trunc((width - w) / 2), Math.trunc((height - h) / 2), w, h]);
  }
}

if (!customElements.get('inkwire-conference')) customElements.define('inkwire-conference', InkwireConference);
