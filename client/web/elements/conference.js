// <inkwire-conference server="ws://HOST:PORT/ws" session="NAME">: a viewer of a conference
// session (SPEC W3): the speaker's neutral photo and its landmarks once, then expression codes
// only (8 bytes each), the photo deformed by each code's template as the C++ client deforms it
// (render/face/face_reconstructor.js). Sized by its container at the device pixel ratio; the
// photo fitted and centred. Property `expression` ({code, intensity}); attribute `loaded` once
// the photo is there.
import { parseLandmarks, parseTemplates, kExpressionNames } from '../common/face.js';
import { AssetKind, Session } from '../net/session.js';
import { FaceReconstructor } from '../render/face/face_reconstructor.js';
import { loadTweenShaders } from '../render/tween/tween_view.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 120px; background: #fff; }
  canvas { width: 100%; height: 100%; display: block; }
  .message { position: absolute; inset: auto 8px 8px 8px; font: 13px system-ui, sans-serif; color: #a33; text-align: center; }
</style>
<canvas part="canvas"></canvas><div class="message" role="status"></div>`;

async function pixels(bytes) {
  const bitmap = await createImageBitmap(new Blob([bytes]), { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d', { willReadFrequently: true });
  context.drawImage(bitmap, 0, 0);
  return { width: bitmap.width, height: bitmap.height, data: context.getImageData(0, 0, bitmap.width, bitmap.height).data };
}

export class InkwireConference extends HTMLElement {
  static observedAttributes = ['server', 'session', 'token'];

  constructor() {
    super();
    this.attachShadow({ mode: 'open' }).innerHTML = template;
    this.canvas = this.shadowRoot.querySelector('canvas');
    this.message = this.shadowRoot.querySelector('.message');
  }

  get expression() { return this.face ? { code: this.face.code, intensity: this.face.intensity, name: kExpressionNames[this.face.code] } : null; }

  connectedCallback() {
    this.setAttribute('role', 'img');
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', `${this.getAttribute('session') ?? 'Conference'}: the speaker's face`);
    new ResizeObserver(() => this.redraw()).observe(this);
    this.start();
  }

  disconnectedCallback() {
    this.session?.close();
    this.session = null;
  }

  attributeChangedCallback(name, before, after) {
    if (this.isConnected && before !== after && before !== null) this.start();
  }

  fail(reason) {
    this.message.textContent = reason;
    this.dispatchEvent(new CustomEvent('error', { detail: reason }));
  }

  start() {
    this.session?.close();
    this.face = null;
    this.removeAttribute('loaded');
    const server = this.getAttribute('server') ?? `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`;
    const session = new Session(server, this.getAttribute('session') ?? '', this.getAttribute('token') ?? '');
    this.session = session;
    let pending = null;  // a code that came before the photo
    session.addEventListener('error', (e) => this.fail(e.detail));
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
          session.fetchAsset(photo).then(pixels),
          session.fetchAsset(marks).then((b) => parseLandmarks(JSON.parse(new TextDecoder().decode(b)))),
          fetch(new URL('../face/expression_templates.json', import.meta.url)).then((r) => r.json()).then(parseTemplates),
          loadTweenShaders(),
        ]);
        if (this.session !== session) return;
        this.gl = this.gl ?? this.canvas.getContext('webgl2', { premultipliedAlpha: true, antialias: false, depth: true });
        if (!this.gl) throw new Error('this browser has no WebGL2');
        this.face = new FaceReconstructor(this.gl, image.data, image.width, image.height, landmarks, templates, shaders);
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

  redraw() {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      const now = performance.now() / 1000;
      this.draw(now);
      if (this.face && !this.face.settled(now)) this.redraw();  // until the tween settles
    });
  }

  draw(now = performance.now() / 1000) {
    const gl = this.gl, face = this.face;
    if (!gl || !face) return;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio)), height = Math.max(1, Math.round(this.canvas.clientHeight * ratio));
    if (this.canvas.width !== width || this.canvas.height !== height) this.canvas.width = width, this.canvas.height = height;
    gl.viewport(0, 0, width, height);
    gl.clearColor(1, 1, 1, 1);
    gl.clearDepth(1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const scale = Math.min(width / face.width, height / face.height);
    const w = Math.round(face.width * scale), h = Math.round(face.height * scale);
    face.draw(now, [width, height], [Math.trunc((width - w) / 2), Math.trunc((height - h) / 2), w, h]);
  }
}

if (!customElements.get('inkwire-conference')) customElements.define('inkwire-conference', InkwireConference);
