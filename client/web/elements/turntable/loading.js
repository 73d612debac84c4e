// <inkwire-turntable>'s loading (SPEC T12, T21): the product, from the session's server or,
// with `src`, from a static host's product.json (net/static_product.js; then only the live part,
// a presenter and followers, goes through a server, and only when `session` is given too); its
// photos one at a time (each matte, then the photo, nearest the current view first, each drawn
// as it comes), its tween cells whenever they arrive, a progress bar, and the attribute `loaded`
// once all are there. A mixin over SessionElement (STYLE 13: one feature a file, as
// <model-viewer> does).
import { nextPhotoFetch, wantedLevel } from '../../common/photo_fetch.js';
import { decodeTweenCell } from '../../common/tween_data.js';
import { AssetKind, bytesBy } from '../../net/session.js';
import { StaticProduct } from '../../net/static_product.js';
import { matteSample, objectOnMatte } from '../../render/tween/matte_sample.js';
import { loadTweenShaders, TweenView } from '../../render/tween/tween_view.js';
import { decodeImage } from '../session_element.js';

// A product photo or matte's RGBA bytes, checked against the size it should have.
async function pixels(bytes, width, height) {
  const image = await decodeImage(bytes);
  if (image.width !== width || image.height !== height) throw new Error(`a photo is ${image.width}x${image.height}, not ${width}x${height}`);
  return image.data;
}

export const LoadingMixin = (Base) => class extends Base {
  start() {
    this.view = null;
    this.removeAttribute('loaded');
    this.startedAt = performance.now();
    this.firstViewPhotos = this.firstViewBytes = undefined;
    this.presented = null;  // a new session hears this view again
    this.presentRefused = false;
    this.product?.close();
    this.product = null;
    const src = this.getAttribute('src');
    if (src) {
      this.session?.close();
      this.session = null;
      this.product = new StaticProduct(src);
      this.product.addEventListener('error', (e) => this.fail(e.detail));
    }
    // The live part: a presenter's views and refusals (with `src`, only when a session is named).
    const live = !src || this.hasAttribute('session') ? this.openSession() : null;
    live?.addEventListener('refused', () => { this.presentRefused = true; });
    live?.addEventListener('state', (e) => {
      if (e.detail.type === 'object-pose') this.follow(e.detail);
    });
    if (src) live?.addEventListener('snapshot', (e) => this.follow(e.detail.object), { once: true });
    const session = this.product ?? live;  // where the product's files come from
    const pendingCells = [];
    session.addEventListener('tween-data', (e) => {
      if (this.view) this.addCell(e.detail);
      else pendingCells.push(e.detail);
    });
    session.addEventListener('snapshot', async (e) => {
      try {
        const snapshot = e.detail;
        if (!snapshot.product.directions.length) throw new Error(`session '${snapshot.session}' has no product to show`);
        this.snapshot = snapshot;
        if (snapshot.object) this.follow(snapshot.object);
        this.view = new TweenView(this.webgl(), snapshot.product, await loadTweenShaders());
        for (const cell of pendingCells.splice(0)) this.addCell(cell);
        await this.download(session);
      } catch (error) {
        if (this.source() === session) this.fail(error.message);
      }
    });
  }

  // Where the product's files come from now: the static host's product, else the session.
  source() { return this.product ?? this.session; }

  disconnectedCallback() {
    super.disconnectedCallback();
    this.product?.close();
    this.product = null;
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

  // The zoom level the view needs (photo_fetch.js), the display's height in device pixels from
  // the last frame drawn.
  wantedLevel() {
    const { height, levels } = this.snapshot.product;
    return wantedLevel(height, levels.map((l) => l.height), (this.displayHeight ?? 0) * this.zoom);
  }

  // What to fetch next (photo_fetch.js): {sample, level}, or null when all the view needs is there.
  nextFetch() {
    const d = this.direction();
    return nextPhotoFetch(this.snapshot.product.directions, d, this.view.viewSamples(d), (i) => !!this.view.textures[i],
                          (i) => this.view.finerLevel(i), this.wantedLevel());
  }

  // Photos one at a time, as nextFetch() says; each drawn as it comes. With nothing to fetch it
  // waits for the next frame drawn (a turn, a zoom, a resize may need more).
  async download(session) {
    const { product, assets } = this.snapshot;
    const nth = (kind) => assets.filter((a) => a.kind === kind);
    const photos = nth(AssetKind.samples), mattes = nth(AssetKind.matte), zoom = nth(AssetKind.zoom);
    const n = product.directions.length;
    for (;;) {
      if (this.source() !== session) return;
      const next = this.nextFetch();
      if (!next) {
        await new Promise((resolve) => { this.wake = resolve; });
        continue;
      }
      const { sample, level } = next;
      const size = level === 0 ? product : product.levels[level - 1];
      const photo = level === 0 ? photos[sample] : zoom[(level - 1) * n + sample];
      if (!photo) throw new Error(`the product lists no photo for sample ${sample}${level ? ` at zoom level ${level}` : ''}`);
      const matte = mattes[sample] ? await pixels(await session.fetchAsset(mattes[sample]), product.width, product.height) : null;
      const photoBytes = await session.fetchAsset(photo);
      // What the first view waits for: the snapshot, one matte and one photo (the tween data the
      // server sends after that photo is for the views between photos).
      if (this.firstViewBytes === undefined) this.firstViewBytes = bytesBy(session, photo);
      const rgba = await pixels(photoBytes, size.width, size.height);
      if (this.source() !== session) return;
      // A finer level is laid on white by its first-level matte scaled up (server/products/matte.cpp key_like).
      const object = objectOnMatte(rgba, matte, product.width, product.height, size.width, size.height);
      const texture = matteSample(object, size.width, size.height, size.height / product.height);
      if (level === 0) this.view.setSample(sample, texture);
      else this.view.setFiner(sample, level, texture);
      // A static product's cells follow the first view (draw()); an element not drawn (hidden)
      // still gets them, a second after its first photo.
      if (this.product) setTimeout(() => this.product?.startCells(), 1000);
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

};
