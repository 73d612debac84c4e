// <inkwire-turntable>'s loading (SPEC T12, T21): the product as static files (product.json and
// the files it names, net/static_product.js) from `src`, a static host or CDN, or else from the
// session's server, which serves them the same way; its photos one at a time (each matte, then
// the photo, nearest the current view first, each drawn as it comes), its tween cells after the
// first view, a progress bar, and the attribute `loaded` once all are there. Only the live part,
// a presenter and followers, goes through a WebSocket. A mixin over SessionElement (one
// feature a file, as <model-viewer> does).
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
    this.session?.close();
    this.session = null;
    this.liveJoined = false;
    this.product = new StaticProduct(this.productUrl());
    this.product.addEventListener('error', (e) => this.fail(e.detail));
    this.goLive();
    const product = this.product;
    // Cells are fetched only after the first photo (startCells), when the view is there.
    product.addEventListener('tween-data', (e) => this.addCell(e.detail));
    product.addEventListener('snapshot', async (e) => {
      try {
        this.snapshot = e.detail;
        this.view = new TweenView(this.webgl(), this.snapshot.product, await loadTweenShaders());
        await this.download(product);
      } catch (error) {
        if (this.product === product) this.fail(error.message);
      }
    });
  }

  // Where the product's files are: `src`, else the session's server, which serves every product
  // as a static host serves its export (/products/NAME/product.json): one way to load either.
  productUrl() {
    const src = this.getAttribute('src');
    if (src) return src;
    const server = new URL(this.serverUrl());
    const url = new URL(`/products/${encodeURIComponent(this.getAttribute('session') ?? '')}/product.json`, `${server.protocol === 'wss:' ? 'https' : 'http'}://${server.host}`);
    if (this.joinToken()) url.searchParams.set('token', this.joinToken());
    return url.href;
  }

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
  async download(source) {
    const { product, assets } = this.snapshot;
    const nth = (kind) => assets.filter((a) => a.kind === kind);
    const photos = nth(AssetKind.samples), mattes = nth(AssetKind.matte), zoom = nth(AssetKind.zoom);
    const n = product.directions.length;
    for (;;) {
      if (this.product !== source) return;
      const next = this.nextFetch();
      if (!next) {
        await new Promise((resolve) => { this.wake = resolve; });
        continue;
      }
      const { sample, level } = next;
      const size = level === 0 ? product : product.levels[level - 1];
      const photo = level === 0 ? photos[sample] : zoom[(level - 1) * n + sample];
      if (!photo) throw new Error(`the product lists no photo for sample ${sample}${level ? ` at zoom level ${level}` : ''}`);
      const matte = mattes[sample] ? await pixels(await source.fetchAsset(mattes[sample]), product.width, product.height) : null;
      const photoBytes = await source.fetchAsset(photo);
      // What the first view waits for: the snapshot, one matte and one photo (the tween data the
      // server sends after that photo is for the views between photos).
      if (this.firstViewBytes === undefined) this.firstViewBytes = bytesBy(source, photo);
      const rgba = await pixels(photoBytes, size.width, size.height);
      if (this.product !== source) return;
      // A finer level is laid on white by its first-level matte scaled up (server/products/matte.cpp key_like).
      const object = objectOnMatte(rgba, matte, product.width, product.height, size.width, size.height);
      const texture = matteSample(object, size.width, size.height, size.height / product.height);
      if (level === 0) this.view.setSample(sample, texture);
      else this.view.setFiner(sample, level, texture);
      // The tween cells follow the first view (draw()); an element not drawn (hidden) still gets
      // them, a second after its first photo.
      setTimeout(() => source.startCells(), 1000);
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
