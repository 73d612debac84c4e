// What both elements are made of (one custom element per use, shared behaviour in one
// place): a shadow root from a template, a session opened from the `server`, `session` and `token`
// attributes (the page's own server by default) and closed when the element leaves the page, a
// one-line message for what went wrong, a WebGL2 canvas sized by the container at the device
// pixel ratio, and redraws coalesced into animation frames.
import { Session } from '../net/session.js';

// Decoded RGBA bytes of an image file's bytes, as they are (no colour management, no
// premultiplying): {width, height, data}.
export async function decodeImage(bytes) {
  const bitmap = await createImageBitmap(new Blob([bytes]), { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
  const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
  const context = canvas.getContext('2d', { willReadFrequently: true });
  context.drawImage(bitmap, 0, 0);
  return { width: bitmap.width, height: bitmap.height, data: context.getImageData(0, 0, bitmap.width, bitmap.height).data };
}

// The browser's renderer (client/web/module: the native client's C++ compiled to WebAssembly)
// from the server at `server` (a ws:// or wss:// address), drawing into `canvas`: {module,
// bytes} (what the page fetched of it). Throws with the reason when it cannot be loaded.
export async function loadRenderModule(server, canvas) {
  const url = new URL(server);
  url.protocol = url.protocol === 'wss:' ? 'https:' : 'http:';
  url.pathname = '/module/inkwire-scene.js';
  url.search = '';
  let create;
  try {
    ({ default: create } = await import(url.href));
  } catch (error) {
    throw new Error(`the renderer cannot be loaded from ${url.href}: ${error.message}`);
  }
  // The module draws into the element's canvas, which no selector reaches inside the shadow
  // root: it is named to the module as a special target.
  const module = await create({ print: () => {}, printErr: (text) => console.warn(text) });
  module.specialHTMLTargets['!canvas'] = canvas;
  const bytes = performance.getEntriesByType('resource').filter((r) => r.name.includes('/module/inkwire-scene.'))
    .reduce((sum, r) => sum + (r.transferSize || r.encodedBodySize || 0), 0);
  return { module, bytes };
}

// Sizes `canvas` to its box at the device pixel ratio; true when its size changed (which clears
// its drawing buffer: a frame is due).
export function fitCanvas(canvas) {
  const ratio = window.devicePixelRatio || 1;
  const width = Math.max(1, Math.round(canvas.clientWidth * ratio)), height = Math.max(1, Math.round(canvas.clientHeight * ratio));
  if (canvas.width === width && canvas.height === height) return false;
  canvas.width = width, canvas.height = height;
  return true;
}

// `bytes` lent to the module for as long as `use(address, size)` reads them.
export function lendBytes(module, bytes, use) {
  const address = module._malloc(Math.max(1, bytes.length));
  try {
    module.HEAPU8.set(bytes, address);
    return use(address, bytes.length);
  } finally {
    module._free(address);
  }
}

export class SessionElement extends HTMLElement {
  static observedAttributes = ['server', 'session', 'token'];

  constructor(template) {
    super();
    this.attachShadow({ mode: 'open' }).innerHTML = template;
    this.canvas = this.shadowRoot.querySelector('canvas');
    this.message = this.shadowRoot.querySelector('.message');
  }

  // What connectedCallback adds, disconnectedCallback removes: listeners are added
  // with `this.connection` (an AbortSignal) and go with it, the observer is disconnected.
  connectedCallback() {
    this.setAttribute('role', 'img');
    this.aborter = new AbortController();
    this.resizeObserver = new ResizeObserver(() => this.redraw());
    this.resizeObserver.observe(this);
    this.start();
  }

  get connection() { return this.aborter.signal; }

  disconnectedCallback() {
    this.aborter?.abort();
    this.resizeObserver?.disconnect();
    this.resizeObserver = null;
    this.session?.close();
    this.session = null;
  }

  attributeChangedCallback(name, before, after) {
    if (this.isConnected && before !== after && before !== null) this.start();
  }

  // What went wrong, on the element's face and as its `reason` (read by tests and the page).
  fail(reason) {
    this.reason = reason;
    this.message.textContent = reason;
    this.dispatchEvent(new CustomEvent('error', { detail: reason }));
  }

  // A change the server refused (this member may not make it): said, and the element goes on.
  refused(reason) {
    this.message.textContent = `Refused: ${reason}`;
    this.dispatchEvent(new CustomEvent('refused', { detail: reason }));
  }

  // The WebSocket address of the session's server: the `server` attribute, else the page's own.
  serverUrl() { return this.getAttribute('server') ?? `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`; }

  // The token joining the session.
  joinToken() { return this.getAttribute('token') ?? ''; }

  // A new session from the attributes, replacing any before it. `websocketsOpened` counts them
  // (a product read from a static host opens none).
  openSession() {
    this.session?.close();
    this.websocketsOpened = (this.websocketsOpened ?? 0) + 1;
    this.session = new Session(this.serverUrl(), this.getAttribute('session') ?? '', this.joinToken());
    this.session.addEventListener('error', (e) => this.fail(e.detail));
    this.session.addEventListener('refused', (e) => this.refused(e.detail));
    return this.session;
  }

  webgl() {
    this.gl = this.gl ?? this.canvas.getContext('webgl2', { premultipliedAlpha: true, antialias: false, depth: true });
    if (!this.gl) throw new Error('this browser has no WebGL2');
    return this.gl;
  }

  // Sizes the canvas to its box at the device pixel ratio and clears it to white; [width, height].
  beginFrame() {
    const gl = this.gl;
    fitCanvas(this.canvas);
    const { width, height } = this.canvas;
    gl.viewport(0, 0, width, height);
    gl.clearColor(1, 1, 1, 1);
    gl.clearDepth(1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    return [width, height];
  }

  redraw() {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame(() => {
      this.frameRequested = false;
      this.draw();
      if (this.animating?.()) this.redraw();
    });
  }
}
