// A product read from a static host or CDN (SPEC T21): its manifest (product.json, fetched
// afresh each visit) and its files over plain HTTP(S) with fetch(), each checked against its
// hash, kept by the browser's HTTP cache (their names never change) and Cache Storage, as the
// session's own assets are. No WebSocket: it gives <inkwire-turntable>'s loading what a Session
// gives it ('snapshot', 'tween-data', 'error' events, fetchAsset, byte counts); the tween cells
// when the element has drawn its first view (startCells), so nothing comes before it but the
// manifest, a photo and its matte.
import { AssetKind } from '../protocol/messages.js';
import { parseManifest } from './product_manifest.js';
import { cachedOrFetched, toHex } from './session.js';

const fromHex = (hex) => Uint8Array.from(hex.match(/../g), (b) => parseInt(b, 16));

export class StaticProduct extends EventTarget {
  constructor(src) {
    super();
    this.srcText = src;
    this.bytesReceived = 0;  // and receivedBy: what the first view waited for (bytesBy)
    this.receivedBy = new Map();
    this.closed = false;
    this.cellsAsked = false;
    this.load().catch((error) => this.fail(error.message));
  }

  close() { this.closed = true; }

  fail(reason) {
    if (!this.closed) this.dispatchEvent(new CustomEvent('error', { detail: reason }));
  }

  async get(url, what) {
    let response;
    try {
      response = await fetch(url, { mode: 'cors', cache: what === 'manifest' ? 'no-cache' : 'default' });
    } catch (error) {
      throw new Error(`the product's ${what} cannot be fetched from ${url.href}: ${error.message}`);
    }
    if (!response.ok) {
      // A server's plain-text reason (inkwire-server says why: no such product, a token needed).
      const why = response.headers.get('content-type')?.startsWith('text/plain') ? (await response.text()).split('\n')[0].slice(0, 200) : '';
      throw new Error(`the product's ${what} at ${url.href} answered ${response.status}${why ? `: ${why}` : ''}`);
    }
    const bytes = new Uint8Array(await response.arrayBuffer());
    this.bytesReceived += bytes.length;
    return bytes;
  }

  async load() {
    try {
      this.src = new URL(this.srcText, location.href);
    } catch {
      throw new Error(`src '${this.srcText}' is not an address`);
    }
    const manifest = parseManifest(new TextDecoder().decode(await this.get(this.src, 'manifest')));
    if (this.closed) return;
    this.manifest = manifest;
    const asset = (f, kind, name) => ({ kind, hash: fromHex(f.sha256), size: f.size, name, file: f.file });
    const assets = [
      ...manifest.photos.map((f, i) => asset(f, AssetKind.samples, `photo ${i}`)),
      ...manifest.mattes.map((f, i) => asset(f, AssetKind.matte, `matte ${i}`)),
      ...manifest.zoom.flatMap((level, l) => level.map((f, i) => asset(f, AssetKind.zoom, `zoom ${l + 1} photo ${i}`))),
    ];
    this.dispatchEvent(new CustomEvent('snapshot', { detail: { session: manifest.name, product: manifest.product, assets, object: null } }));
  }

  // The asset's bytes: from Cache Storage or the host, checked against its hash.
  async fetchAsset(asset) {
    const bytes = await cachedOrFetched(asset, () => this.get(new URL(asset.file, this.src), asset.name));
    this.receivedBy.set(toHex(asset.hash), this.bytesReceived);
    return bytes;
  }

  // The tween cells, one after another, each as a 'tween-data' event; once.
  startCells() {
    if (this.cellsAsked || !this.manifest) return;
    this.cellsAsked = true;
    this.fetchCells().catch((error) => this.fail(error.message));
  }

  async fetchCells() {
    for (const cell of this.manifest.cells) {
      if (this.closed) return;
      const data = await cachedOrFetched({ hash: fromHex(cell.sha256), name: `tween cell ${cell.pair}` }, () => this.get(new URL(cell.file, this.src), `tween cell ${cell.pair}`));
      if (!this.closed) this.dispatchEvent(new CustomEvent('tween-data', { detail: { pair: cell.pair, data } }));
    }
  }
}
