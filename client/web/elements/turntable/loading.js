// <inkwire-turntable>'s loading (SPEC T12): the session's product, its photos one at a time
// (each matte, then the photo, nearest the current view first, each drawn as it comes), its
// tween cells whenever they arrive, a progress bar, and the attribute `loaded` once all are
// there. A mixin over SessionElement (STYLE 13: one feature a file, as <model-viewer> does).
import { decodeTweenCell } from '../../common/tween_data.js';
import { AssetKind, bytesBy } from '../../net/session.js';
import { matteSample } from '../../render/tween/matte_sample.js';
import { loadTweenShaders, TweenView } from '../../render/tween/tween_view.js';
import { decodeImage } from '../session_element.js';

// A product photo or matte's RGBA bytes, checked against the product's size.
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

};
