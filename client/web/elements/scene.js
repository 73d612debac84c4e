// <inkwire-scene server="ws://HOST:PORT/ws" session="NAME">: a shared NPR scene (SPEC W6): the
// session's model in its style from its camera, drawn by the native client's own renderers
// compiled to WebAssembly (client/web/module, loaded from the server's /module/). Drag orbits and
// the wheel zooms, shared with the session as the native window does; a style menu and a panel of
// the style's parameters send every change to all; changes from other members show at once.
// Attributes: server, session, token, editor-token (joins as an editor: a session that names one
// lets only editors steer; what the server will refuse this member it says on joining, and those
// controls are off with the reason beside them); `loaded` once the module and
// model are there and the first frame is drawn (and `modelName`, the model's file name; a model
// the editor replaces arrives in a new snapshot and is drawn as the first was). Properties: styleName, settings (object),
// camera ({azimuth, elevation, distance}); setting them changes the session as the panel would.
import { fitCanvas, lendBytes, loadRenderModule, SessionElement } from './session_element.js';
import { AssetKind } from '../net/session.js';
import { ScenePanel } from './scene/panel.js';

const template = `
<style>
  :host { display: block; position: relative; width: 100%; height: 100%; min-height: 160px; background: #eee; outline: none;
          touch-action: none; user-select: none; font: 13px system-ui, sans-serif; }
  canvas { width: 100%; height: 100%; display: block; cursor: grab; }
  canvas.dragging { cursor: grabbing; }
  canvas.following { cursor: default; }
  .progress { position: absolute; left: 10%; right: 10%; bottom: 12px; height: 4px; background: #0001; border-radius: 2px; }
  .bar { height: 100%; width: 0; background: #3a6ea5; border-radius: 2px; transition: width 0.2s; }
  .message { position: absolute; inset: auto 8px 24px 8px; color: #a33; text-align: center; }
  details { position: absolute; top: 8px; right: 8px; max-height: calc(100% - 16px); overflow: auto; background: #fffe;
            border-radius: 6px; padding: 4px 8px; max-width: 300px; }
  summary { cursor: pointer; }
  label { display: grid; grid-template-columns: 1fr auto; gap: 4px; margin: 4px 0; align-items: center; }
  input[type=range] { width: 110px; }
  .note { color: #666; font-size: 12px; margin: 4px 0; }
</style>
<canvas part="canvas"></canvas>
<div class="progress" part="progress" role="progressbar" aria-valuemin="0" aria-valuemax="100"><div class="bar"></div></div>
<div class="message" role="status"></div>
<details part="panel"><summary>Style</summary><div class="panel"></div></details>`;

// Dragging and the wheel as the native window does (client/viewer/window_input.cpp).
const kDegreesPerPixel = 0.4, kMaxElevation = 85, kWheelStep = 0.9, kMinDistance = 0.25, kMaxDistance = 20;

export class InkwireScene extends SessionElement {
  static observedAttributes = [...SessionElement.observedAttributes, 'editor-token'];

  constructor() {
    super(template);
    this.bar = this.shadowRoot.querySelector('.bar');
    this.panel = new ScenePanel(this.shadowRoot.querySelector('.panel'), (name, settings) => this.changeStyle(name, settings));
    this._styleName = 'default';
    this._settings = {};
    this.orbit = { azimuth: 30, elevation: 20, distance: 1.4 };
    this.sequence = 0;
  }

  get styleName() { return this._styleName; }
  set styleName(name) { this.changeStyle(String(name), this._settings); }
  get settings() { return { ...this._settings }; }
  set settings(values) { this.changeStyle(this._styleName, { ...values }); }
  get camera() { return { ...this.orbit }; }
  set camera(orbit) { this.moveCamera({ ...this.orbit, ...orbit }); }

  connectedCallback() {
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    super.connectedCallback();
    this.setAttribute('aria-label', `${this.getAttribute('session') ?? 'Scene'}: drag to turn, wheel to zoom`);
    const signal = this.connection;
    this.canvas.addEventListener('pointerdown', (e) => this.pointerDown(e), { signal });
    this.canvas.addEventListener('pointermove', (e) => this.pointerMove(e), { signal });
    for (const type of ['pointerup', 'pointercancel']) this.canvas.addEventListener(type, (e) => this.pointerUp(e), { signal });
    this.canvas.addEventListener('wheel', (e) => this.wheel(e), { signal, passive: false });
  }

  // An editor joins with the editor token (the server then lets it steer a session that names
  // one): the attribute, else the key this browser keeps for a scene it made (pages/upload.js).
  joinToken() {
    let kept = null;
    try {
      kept = localStorage.getItem(`inkwire-editor-key ${this.serverUrl()} ${this.getAttribute('session') ?? ''}`);
    } catch {}
    return this.getAttribute('editor-token') ?? kept ?? super.joinToken();
  }

  // The session and the module, loaded side by side; the model once both are there.
  async start() {
    this.removeAttribute('loaded');
    this.message.textContent = '';
    this.startedAt = performance.now();
    this.progress(0.05);
    const session = this.openSession();
    const module = this.loadModule(this.serverUrl());
    module.catch((error) => this.fail(error.message));
    session.addEventListener('snapshot', async (e) => {
      try {
        const snapshot = e.detail;
        if (snapshot.kind !== 1) throw new Error(`session '${snapshot.session}' is not a scene`);
        const mesh = snapshot.assets.find((a) => a.kind === AssetKind.mesh);
        if (!mesh) throw new Error('the scene has no model');
        const [bytes] = await Promise.all([session.fetchAsset(mesh), module]);
        this.progress(0.9);
        this.bytesFirstFrame = session.bytesReceived + (this.moduleBytes ?? 0);
        // A second snapshot brings a replaced model (SPEC N8): drawn in the same style from the same camera.
        const reason = this.loadModel(bytes, mesh.name);
        if (reason) throw new Error(reason);
        this.modelName = mesh.name;
        this.applyStyle(snapshot.style);
        this.applyCamera(snapshot.camera);
        this.applyObject(snapshot.object);
        this.draw();
        this.progress(1);
        this.msFirstFrame = performance.now() - this.startedAt;
        this.setAttribute('loaded', '');
        this.dispatchEvent(new Event('load'));
      } catch (error) {
        this.fail(error.message);
      }
    });
    session.addEventListener('permissions', (e) => this.applyPermissions(e.detail));
    session.addEventListener('state', (e) => {
      const m = e.detail;
      if (m.type === 'style-change') this.applyStyle(m);
      else if (m.type === 'camera-pose') this.applyCamera(m);
      else if (m.type === 'object-pose') this.applyObject(m);
      this.redraw();
    });
  }

  async loadModule(server) {
    if (this.view) return;
    ({ module: this.module, bytes: this.moduleBytes } = await loadRenderModule(server, this.canvas));
    this.progress(0.4);
    this.view = new this.module.SceneView('!canvas');
    const reason = this.view.error();
    if (reason) throw new Error(reason);
    const styles = JSON.parse(this.module.stylesJson());
    this.panel.setStyles(styles, (name) => JSON.parse(this.module.styleParamsJson(name)));
    this.progress(0.6);
  }

  // The model's bytes lent to the module for as long as it reads them; "" or why it cannot.
  loadModel(bytes, name) { return lendBytes(this.module, bytes, (address, size) => this.view.loadModel(address, size, name)); }

  progress(share) {
    this.bar.style.width = `${Math.round(share * 100)}%`;
    this.bar.parentElement.hidden = share >= 1;
  }

  // The session's style, as the module draws it and the panel shows it; a style the module
  // refuses keeps the picture before it and says why.
  applyStyle(style) {
    this._styleName = style.renderer;
    this._settings = Object.fromEntries(style.settings.map((s) => [s.slice(0, s.indexOf('=')), s.slice(s.indexOf('=') + 1)]));
    if (!this.view) return;
    const reason = this.view.setStyle(style.renderer, JSON.stringify(style.settings));
    this.message.textContent = reason ? `Style '${style.renderer}' cannot be drawn here: ${reason}` : '';
    this.panel.show(style.renderer, this._settings);
  }

  applyCamera(pose) {
    this.pose = pose;
    this.orbit = JSON.parse(this.module?.orbitOfJson(...pose.position, ...pose.target) ?? JSON.stringify(this.orbit));
    this.view?.setCamera(...pose.position, ...pose.target, ...pose.up, pose.fov_y_degrees);
  }

  applyObject(pose) { this.view?.setObjectPose(...pose.rotation, ...pose.translation, pose.scale); }

  // What the server will refuse this member, said on joining: the panel locked with the reason,
  // and dragging and the wheel off (the reason as the canvas's tooltip) when it may not steer.
  applyPermissions(refused) {
    const reasons = new Map(refused.map((r) => [r.change, r.reason]));
    this.panel.lock(reasons.get('style-change') ?? null);
    this.steeringRefused = reasons.get('camera-pose') ?? null;
    this.canvas.classList.toggle('following', Boolean(this.steeringRefused));
    this.canvas.title = this.steeringRefused ?? '';
  }

  changeStyle(name, settings) {
    const style = { type: 'style-change', renderer: name, settings: Object.entries(settings).map(([k, v]) => `${k}=${v}`) };
    this.applyStyle(style);
    this.session?.send(style);
    this.redraw();
  }

  // A new orbit: drawn at once and sent to the session (the sender applies its own change).
  moveCamera(orbit) {
    if (!this.module) return;
    orbit.elevation = Math.min(kMaxElevation, Math.max(-kMaxElevation, orbit.elevation));
    orbit.distance = Math.min(kMaxDistance, Math.max(kMinDistance, orbit.distance));
    const pose = JSON.parse(this.module.orbitPoseJson(orbit.azimuth, orbit.elevation, orbit.distance));
    const message = { type: 'camera-pose', sequence: ++this.sequence, position: pose.position, target: pose.target, up: pose.up, fov_y_degrees: pose.fov };
    this.applyCamera(message);
    this.orbit = orbit;
    this.session?.send(message);
    this.redraw();
  }

  pointerDown(e) {
    if (this.steeringRefused) return;
    this.canvas.setPointerCapture(e.pointerId);
    this.canvas.classList.add('dragging');
    this.dragFrom = [e.clientX, e.clientY];
  }

  pointerMove(e) {
    if (!this.dragFrom) return;
    const [x, y] = this.dragFrom;
    this.dragFrom = [e.clientX, e.clientY];
    this.moveCamera({ ...this.orbit, azimuth: this.orbit.azimuth - (e.clientX - x) * kDegreesPerPixel,
                      elevation: this.orbit.elevation + (e.clientY - y) * kDegreesPerPixel });
  }

  pointerUp() {
    this.dragFrom = null;
    this.canvas.classList.remove('dragging');
  }

  wheel(e) {
    if (this.steeringRefused) return;
    e.preventDefault();
    this.moveCamera({ ...this.orbit, distance: this.orbit.distance * kWheelStep ** Math.sign(e.deltaY) });
  }

  // One frame at the device pixel ratio; `seconds` of animation time (boiling lines, brushes),
  // by default the time since the element started.
  draw(seconds) {
    if (!this.view) return;
    fitCanvas(this.canvas);
    const reason = this.view.draw(seconds ?? (performance.now() - this.startedAt) / 1000);
    if (reason) this.message.textContent = reason;
    this.framesDrawn = (this.framesDrawn ?? 0) + 1;
  }

  // Styles that change on their own (boiling lines, drifting brushes) keep drawing.
  animating() { return this.hasAttribute('loaded') && this.view?.redrawHz() > 0; }

  disconnectedCallback() {
    super.disconnectedCallback();
    this.view?.delete();
    this.view = null;
  }
}

if (!customElements.get('inkwire-scene')) customElements.define('inkwire-scene', InkwireScene);
