// <inkwire-turntable server="ws://HOST:PORT/ws" session="NAME">: a product a shop embeds with
// one script tag (SPEC W2, CONTRACTS.md). It downloads the product progressively (each photo's
// matte and photo, nearest the view first; a first view after one photo; a progress bar), then
// synthesises every view locally (render/tween/tween_view.js). Drag with mouse, touch or pen
// (with inertia), wheel or pinch to zoom, arrow keys step one photo, auto-spin until the first
// touch (not under prefers-reduced-motion), fullscreen, sized by its container at the device
// pixel ratio. Turning it sends nothing. Attributes: server, session, token, azimuth,
// auto-rotate ("off" to stop it), and presenter mode (off unless set): `present` sends this
// view to the session as object poses, `follow` shows the newest view a presenter sent (a drag
// turns it until the next); property azimuth (degrees); attribute `loaded` once every photo and
// tween cell is there.
import { decodeTweenCell } from '../common/tween_data.js';
import { poseOfView, viewOfPose } from '../common/turntable_pose.js';
import { AssetKind, bytesBy } from '../net/session.js';
import { matteSample } from '../render/tween/matte_sample.js';
import { loadTweenShaders, TweenView } from '../render/tween/tween_view.js';
import { decodeImage, SessionElement } from './session_element.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 120px; background: #fff; outline: none;
          touch-action: none; user-select: none; }
  canvas { width: 100%; height: 100%; display: block; cursor: grab; }
  canvas.dragging { cursor: grabbing; }
  .progress { position: absolute; left: 10%; right: 10%; bottom: 12px; height: 4px; background: #0001; border-radius: 2px; }
  .bar { height: 100%; width: 0; background: #3a6ea5; border-radius: 2px; transition: width 0.2s; }
  .message { position: absolute; inset: auto 8px 24px 8px; font: 13px system-ui, sans-serif; color: #a33; text-align: center; }
  button { position: absolute; top: 8px; right: 8px; font: 16px system-ui; border: 0; background: #0000000d; border-radius: 4px;
           width: 32px; height: 32px; cursor: pointer; }
</style>
<canvas part="canvas"></canvas>
<div class="progress" part="progress" role="progressbar" aria-valuemin="0" aria-valuemax="100"><div class="bar"></div></div>
<div class="message" role="status"></div>
<button part="fullscreen" aria-label="Full screen" title="Full screen"><svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"
  fill="none" stroke="#333" stroke-width="1.6"><path d="M1 5V1h4M11 1h4v4M15 11v4h-4M5 15H1v-4"/></svg></button>`;

const kDegreesPerPixel = 0.4;  // as the C++ window turns
const kAutoSpin = 20;          // degrees per second until the first touch

// A product photo or matte's RGBA bytes, checked against the product's size.
async function pixels(bytes, width, height) {
  const image = await decodeImage(bytes);
  if (image.width !== width || image.height !== height) throw new Error(`a photo is ${image.width}x${image.height}, not ${width}x${height}`);
  return image.data;
}

export class InkwireTurntable extends SessionElement {
  static observedAttributes = [...SessionElement.observedAttributes, 'azimuth'];

  constructor() {
    super(template);
    this.bar = this.shadowRoot.querySelector('.bar');
    this._azimuth = 0;
    this.elevation = 0;
    this.zoom = 1;
    this.velocity = 0;
    this.touched = false;
    this.pointers = new Map();
  }

  get azimuth() { return this._azimuth; }
  set azimuth(degrees) {
    this._azimuth = Number(degrees) || 0;
    this.redraw();
  }

  connectedCallback() {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('aria-label')) this.setAttribute('aria-label', `${this.getAttribute('session') ?? 'Product'}: drag or use the arrow keys to turn it`);
    super.connectedCallback();
    this.shadowRoot.querySelector('button').addEventListener('click', () => (document.fullscreenElement ? document.exitFullscreen() : this.requestFullscreen()),
                                                             { signal: this.connection });
    this.listen(this.connection);
    this.spin(this.connection);
  }

  attributeChangedCallback(name, before, after) {
    if (name === 'azimuth') this.azimuth = after;
    else super.attributeChangedCallback(name, before, after);
  }

  start() {
    this.view = null;
    this.removeAttribute('loaded');
    this.startedAt = performance.now();
    this.firstViewPhotos = this.firstViewBytes = undefined;
    this.presented = null;  // a new session hears this view again
    this.presentRefused = false;
    const session = this.openSession();
    const pendingCells = [];
    session.addEventListener('tween-data', (e) => {
      if (this.view) this.addCell(e.detail);
      else pendingCells.push(e.detail);
    });
    session.addEventListener('refused', () => { this.presentRefused = true; });
    session.addEventListener('state', (e) => {
      if (e.detail.type === 'object-pose') this.follow(e.detail);
    });
    session.addEventListener('snapshot', async (e) => {
      try {
        const snapshot = e.detail;
        if (!snapshot.product.directions.length) throw new Error(`session '${snapshot.session}' has no product to show`);
        this.snapshot = snapshot;
        this.follow(snapshot.object);
        this.view = new TweenView(this.webgl(), snapshot.product, await loadTweenShaders());
        for (const cell of pendingCells.splice(0)) this.addCell(cell);
        await this.download(session);
      } catch (error) {
        if (this.session === session) this.fail(error.message);
      }
    });
  }

  addCell({ pair, data }) {
    const { width, height, directions } = this.snapshot.product;
    try {
      this.view.addCell(pair, decodeTweenCell(data, width, height, directions.length));
    } catch (error) {
      this.fail(`tween cell ${pair} refused: ${error.message}`);
    }
    this.progress();
    this.redraw();
  }

  direction() {
    const az = (this._azimuth * Math.PI) / 180, el = (this.elevation * Math.PI) / 180;
    return [Math.cos(el) * Math.sin(az), Math.sin(el), Math.cos(el) * Math.cos(az)];
  }

  // Photos one at a time, the nearest to the current view first; each drawn as it comes.
  async download(session) {
    const { product, assets } = this.snapshot;
    const nth = (kind) => assets.filter((a) => a.kind === kind);
    const photos = nth(AssetKind.samples), mattes = nth(AssetKind.matte);
    const have = new Array(product.directions.length).fill(false);
    for (;;) {
      const d = this.direction();
      let next = -1, best = -2;
      product.directions.forEach((s, i) => {
        const c = s[0] * d[0] + s[1] * d[1] + s[2] * d[2];
        if (!have[i] && c > best) best = c, next = i;
      });
      if (next < 0 || this.session !== session) break;
      const matte = mattes[next] ? await pixels(await session.fetchAsset(mattes[next]), product.width, product.height) : null;
      const photoBytes = await session.fetchAsset(photos[next]);
      // What the first view waits for: the snapshot, one matte and one photo (the tween data the
      // server sends after that photo is for the views between photos).
      if (this.firstViewBytes === undefined) this.firstViewBytes = bytesBy(session, photos[next]);
      const photo = await pixels(photoBytes, product.width, product.height);
      if (this.session !== session) return;
      this.view.setSample(next, matteSample(photo, matte, product.width, product.height));
      have[next] = true;
      this.progress();
      this.redraw();
    }
  }

  progress() {
    if (!this.view) return;
    const total = this.view.textures.length + this.view.cells.length, done = this.view.samplesLoaded + this.view.cellsLoaded;
    this.bar.style.width = `${(100 * done) / total}%`;
    this.bar.parentElement.setAttribute('aria-valuenow', String(Math.round((100 * done) / total)));
    if (done === total) {
      this.bar.parentElement.hidden = true;
      this.setAttribute('loaded', '');
      this.dispatchEvent(new Event('load'));
    }
  }

  // Following: the presenter's view replaces this one.
  follow(pose) {
    if (!this.hasAttribute('follow')) return;
    const { azimuth, elevation, zoom } = viewOfPose(pose);
    this.touched = true;  // no auto-spin of its own
    this.velocity = 0;
    this.elevation = elevation;
    this.zoom = zoom;
    this.azimuth = azimuth;
  }

  // Presenting: the view goes to the session whenever it changes, at most once a frame; a
  // presenter the server refused (only the product's editor presents) stops sending.
  present() {
    if (!this.hasAttribute('present') || this.presentRefused || !this.session || !this.snapshot) return;
    const view = [this._azimuth, this.elevation, this.zoom];
    if (this.presented && view.every((v, i) => v === this.presented[i])) return;
    this.presented = view;
    this.poseSequence = (this.poseSequence ?? 0) + 1;
    this.session.send(poseOfView(...view, this.poseSequence));
  }

  // Drawn at once (tests and screenshots read the canvas right after).
  draw() {
    if (!this.gl || !this.view) return;
    this.present();
    const [width, height] = this.beginFrame();
    if (this.view.draw([width, height], this.direction(), this.zoom) && this.firstViewPhotos === undefined) {
      // What the first view waited for, for measuring: photos, milliseconds since start.
      this.firstViewPhotos = this.view.samplesLoaded;
      this.firstViewMs = performance.now() - this.startedAt;
    }
  }

  // Auto-spin until the first touch, unless motion is unwelcome; then inertia after a drag. One
  // loop while the element is in the page, whatever its attributes do; it ends with `signal`.
  spin(signal) {
    const reduced = window.matchMedia?.('(prefers-reduced-motion: reduce)').matches;
    let last = performance.now();
    const step = (now) => {
      const dt = Math.min((now - last) / 1000, 0.1);
      last = now;
      if (signal.aborted) return;
      if (!this.touched && !reduced && this.getAttribute('auto-rotate') !== 'off' && this.hasAttribute('loaded')) this.azimuth = this._azimuth + kAutoSpin * dt;
      else if (Math.abs(this.velocity) > 2 && this.pointers.size === 0) {
        this.azimuth = this._azimuth + this.velocity * dt;
        this.velocity *= Math.exp(-dt / 0.4);
      }
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  // Pointer, wheel and key handlers, removed with `signal` (when the element leaves the page).
  listen(signal) {
    const c = this.canvas, options = { signal };
    c.addEventListener('pointerdown', (e) => {
      this.touched = true;
      this.velocity = 0;
      c.setPointerCapture(e.pointerId);
      this.pointers.set(e.pointerId, { x: e.clientX, y: e.clientY, t: e.timeStamp });
      c.classList.add('dragging');
    }, options);
    c.addEventListener('pointermove', (e) => {
      const p = this.pointers.get(e.pointerId);
      if (!p) return;
      if (this.pointers.size === 2) {  // pinch: zoom by the change in the pointers' spread
        const [a, b] = [...this.pointers.values()];
        const before = Math.hypot(a.x - b.x, a.y - b.y);
        p.x = e.clientX, p.y = e.clientY;
        const after = Math.hypot(a.x - b.x, a.y - b.y);
        if (before > 0) this.setZoom(this.zoom * (after / before));
        return;
      }
      const dx = e.clientX - p.x, dt = Math.max((e.timeStamp - p.t) / 1000, 1e-3);
      this.azimuth = this._azimuth - dx * kDegreesPerPixel;
      // Inertia follows the last moments of the drag, at most a turn a second.
      this.velocity = Math.min(Math.max(0.7 * this.velocity + 0.3 * ((-dx * kDegreesPerPixel) / dt), -360), 360);
      Object.assign(p, { x: e.clientX, y: e.clientY, t: e.timeStamp });
    }, options);
    const up = (e) => {
      this.pointers.delete(e.pointerId);
      if (this.pointers.size === 0) c.classList.remove('dragging');
    };
    c.addEventListener('pointerup', up, options);
    c.addEventListener('pointercancel', up, options);
    c.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.touched = true;
      this.setZoom(this.zoom * Math.pow(0.9, Math.sign(e.deltaY)));
    }, { passive: false, signal });
    this.addEventListener('keydown', (e) => {
      if (e.key !== 'ArrowLeft' && e.key !== 'ArrowRight' || !this.snapshot) return;
      e.preventDefault();
      this.touched = true;
      this.velocity = 0;
      const dirs = this.snapshot.product.directions, d = this.direction();
      let nearest = 0;
      dirs.forEach((s, i) => { if (s[0] * d[0] + s[2] * d[2] > dirs[nearest][0] * d[0] + dirs[nearest][2] * d[2]) nearest = i; });
      const next = dirs[(nearest + (e.key === 'ArrowRight' ? 1 : -1) + dirs.length) % dirs.length];
      this.azimuth = (Math.atan2(next[0], next[2]) * 180) / Math.PI;
    }, options);
  }

  setZoom(zoom) {
    this.zoom = Math.min(Math.max(zoom, 0.5), 4);
    this.redraw();
  }
}

if (!customElements.get('inkwire-turntable')) customElements.define('inkwire-turntable', InkwireTurntable);
