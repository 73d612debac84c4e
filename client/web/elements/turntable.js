// <inkwire-turntable server="ws://HOST:PORT/ws" session="NAME">, or <inkwire-turntable
// src="https://CDN/PRODUCT/product.json"> for a product exported as static files (SPEC T20-T21;
// the server serves each of its products so too): a product a shop embeds with one script tag
// (SPEC W2, docs/products.md). It downloads the product progressively (each photo's
// matte and photo, nearest the view first; a first view after one photo; a progress bar), then
// synthesises every view locally (render/tween/tween_view.js). Drag with mouse, touch or pen
// (with inertia; up and down too on a product in rows), wheel or pinch to zoom, arrow keys step
// one photo or one row, auto-spin until the first touch (not under prefers-reduced-motion),
// fullscreen, sized by its container at the device pixel ratio. Turning it sends nothing. Attributes: src, server, session, token, azimuth,
// auto-rotate ("off" to stop it), and presenter mode (off unless set): `present` sends this
// view to the session as object poses, `follow` shows the newest view a presenter sent (a drag
// turns it until the next); property azimuth (degrees); attribute `loaded` once every photo and
// tween cell is there.
import { fitScale } from '../common/framing.js';
import { SessionElement } from './session_element.js';
import { AutoSpinMixin } from './turntable/autospin.js';
import { ControlsMixin } from './turntable/controls.js';
import { LoadingMixin } from './turntable/loading.js';
import { PresenterMixin } from './turntable/presenter.js';

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

export class InkwireTurntable extends PresenterMixin(AutoSpinMixin(ControlsMixin(LoadingMixin(SessionElement)))) {
  static observedAttributes = [...SessionElement.observedAttributes, 'azimuth', 'src', 'present', 'follow'];

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
  }

  attributeChangedCallback(name, before, after) {
    if (name === 'azimuth') this.azimuth = after;
    else if (name === 'present' || name === 'follow') this.goLive();
    else super.attributeChangedCallback(name, before, after);
  }

  // Drawn at once (tests and screenshots read the canvas right after).
  draw() {
    if (!this.gl || !this.view) return;
    this.present();
    const [width, height] = this.beginFrame();
    // The photos' height on the display (letterboxed in a narrow element), for the level it needs.
    const { product } = this.snapshot;
    this.displayHeight = height * fitScale(width / height, product.width / product.height);
    this.view.useFiner = this.wantedLevel() > 0;
    if (this.wake) this.wake(), this.wake = null;  // the view may need photos it did not
    if (this.view.draw([width, height], this.direction(), this.zoom) && this.firstViewPhotos === undefined) {
      // What the first view waited for, for measuring: photos, milliseconds since start.
      this.firstViewPhotos = this.view.samplesLoaded;
      this.firstViewMs = performance.now() - this.startedAt;
      this.product?.startCells();  // the tween cells: after the first view, not before it
    }
  }

}

if (!customElements.get('inkwire-turntable')) customElements.define('inkwire-turntable', InkwireTurntable);
