// A thin client's connection to a server over WebSocket (SPEC W1, N3), mirroring
// client/net/session_client.cpp: hello, join, the session's state, tween data, and assets
// fetched in chunks (4 requests ahead) into the browser's cache by content hash, each checked
// against its SHA-256 before use, so a second visit downloads only what changed.
import { AssetKind, decodeFrame, encode, ErrorCode, kMaxChunk } from '../protocol/messages.js';

// As client/net/session_client.hpp (both pinned by tests/golden/warp-vectors.json "session").
export const kRequestsAhead = 4;
// The server pings a quiet client at least every 5 s (protocol/SPEC.md "Deadlines"): this long
// with no word from it and the connection is taken as dead, as client/net/session_client.hpp.
export const kServerSilenceMs = 15000;
const kCacheName = 'inkwire-assets-v1';
// Why a WebSocket to `url` closed before it opened (a refused one tells the page nothing): the
// server answers a plain GET of the same address with its reason, readable by pages of any
// origin ("this server does not accept pages of ORIGIN"), or cannot be reached at all.
export async function whyNotConnected(url) {
  const http = new URL(url);
  http.protocol = http.protocol === 'wss:' ? 'https:' : 'http:';
  let answer;
  try {
    answer = await fetch(http.href, { cache: 'no-store' });
  } catch {
    return `cannot reach the server at ${http.host}`;
  }
  const text = (await answer.text().catch(() => '')).trim();
  // 400 says the address takes WebSockets from this page: the connection failed otherwise.
  return answer.status !== 400 && text ? text : `the server at ${http.host} closed the connection before it opened`;
}

export const toHex = (bytes) => Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');

// An asset's bytes ({hash, name}) from Cache Storage, or from `download()` checked against its
// SHA-256 and then cached: one path for the session's chunks and a static host's files.
export async function cachedOrFetched(asset, download) {
  const key = `/__inkwire/assets/${toHex(asset.hash)}`;
  const cache = globalThis.caches ? await caches.open(kCacheName).catch(() => null) : null;
  const cached = cache && (await cache.match(key));
  if (cached) return new Uint8Array(await cached.arrayBuffer());
  const bytes = await download();
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
  if (toHex(digest) !== toHex(asset.hash)) throw new Error(`${asset.name} does not match its hash`);
  if (cache) await cache.put(key, new Response(bytes)).catch(() => {});
  return bytes;
}

export class Session extends EventTarget {
  // Events: 'snapshot' (detail: the snapshot), 'tween-data' (detail: {pair, data}), 'state' (a
  // style, pose or expression change: detail the message), 'refused' (a change this member may
  // not make: detail the server's reason; the session's own value follows as a 'state'), 'error'
  // (detail: the reason), 'close'; in a call also 'roster', 'member-layers' (and 'member-face' from a
  // server of version 7 or 8), 'voice-frame',
  // 'face-region', 'key-frame-request' and 'voice-route' (detail: the message), 'host-key' (the
  // key of a room this member opened) and 'shut-out' (a locked room or the host's removal: the
  // reason; an 'error' follows).
  // `openRoom`: open a call room of this name when no session has it (SPEC N6), as its host.
  constructor(url, session, token = '', clientName = 'inkwire-web', { openRoom = false } = {}) {
    super();
    this.session = session;
    this.token = token;
    this.openRoom = openRoom;
    this.bytesSent = 0;
    this.bytesReceived = 0;
    // Of those, the heartbeat's (the server's pings and our pongs), which flow whatever the
    // person does: what an action costs is the rest.
    this.keepAliveBytes = { sent: 0, received: 0 };
    this.waiting = new Map();  // hash hex -> {reject, chunk}
    this.receivedBy = new Map();  // hash hex -> bytesReceived when its download completed
    this.socket = new WebSocket(url);
    this.socket.binaryType = 'arraybuffer';
    this.opened = false;
    this.socket.addEventListener('open', () => {
      this.opened = true;
      this.send({ type: 'hello', client_name: clientName });
    });
    this.socket.addEventListener('message', (e) => this.receive(e.data));
    this.lastHeard = performance.now();
    this.silenceTimer = setInterval(() => {
      if (performance.now() - this.lastHeard <= kServerSilenceMs) return;
      this.fail(`no word from the server for ${kServerSilenceMs / 1000} seconds`);
    }, 1000);
    this.socket.addEventListener('close', async () => {
      clearInterval(this.silenceTimer);
      for (const w of this.waiting.values()) w.reject(new Error('connection closed'));
      this.waiting.clear();
      // Refused before it opened (an origin the server does not accept, a server away): said
      // before the close, so whoever listens shows the reason and not only a closed session.
      if (!this.opened && !this.closing) this.dispatchEvent(new CustomEvent('error', { detail: await whyNotConnected(url) }));
      this.dispatchEvent(new Event('close'));
    });
  }

  send(message) {
    const frame = encode(message);
    this.bytesSent += frame.length;
    if (message.type === 'pong') this.keepAliveBytes.sent += frame.length;
    this.socket.send(frame);
  }

  close() {
    this.closing = true;
    clearInterval(this.silenceTimer);
    this.socket.close();
  }

  receive(data) {
    if (!(data instanceof ArrayBuffer)) return this.fail('the server sent a text message');
    this.bytesReceived += data.byteLength;
    this.lastHeard = performance.now();
    let m;
    try {
      m = decodeFrame(new Uint8Array(data));
    } catch (e) {
      return this.fail(`malformed data from the server: ${e.message}`);
    }
    if (m.type === 'welcome') this.send({ type: 'join', session: this.session, token: this.token, open_room: this.openRoom });
    else if (m.type === 'ping') {
      this.keepAliveBytes.received += data.byteLength;
      this.send({ type: 'pong', nonce: m.nonce });
    }
    else if (m.type === 'snapshot') this.dispatchEvent(new CustomEvent('snapshot', { detail: m }));
    else if (m.type === 'tween-data') this.dispatchEvent(new CustomEvent('tween-data', { detail: m }));
    else if (m.type === 'expression-code' || m.type === 'style-change' || m.type === 'camera-pose' || m.type === 'object-pose')
      this.dispatchEvent(new CustomEvent('state', { detail: m }));
    else if (m.type === 'asset-chunk') this.chunk(m);
    else if (m.type === 'roster' || m.type === 'member-layers' || m.type === 'member-face' || m.type === 'voice-frame' || m.type === 'face-region' || m.type === 'key-frame-request' ||
             m.type === 'voice-route')
      this.dispatchEvent(new CustomEvent(m.type, { detail: m }));  // a call's (elements/call.js)
    else if (m.type === 'permissions') this.dispatchEvent(new CustomEvent('permissions', { detail: m.refused }));
    else if (m.type === 'host-key') this.dispatchEvent(new CustomEvent('host-key', { detail: m.key }));
    else if (m.type === 'error' && m.code === ErrorCode['not-allowed']) this.dispatchEvent(new CustomEvent('refused', { detail: m.reason }));
    else if (m.type === 'error') {
      // A locked room or a host's removal: the member is not to come back by itself.
      if (m.code === ErrorCode.locked || m.code === ErrorCode.removed) this.dispatchEvent(new CustomEvent('shut-out', { detail: m.reason }));
      for (const w of this.waiting.values()) w.reject(new Error(m.reason));
      this.waiting.clear();
      this.dispatchEvent(new CustomEvent('error', { detail: m.reason }));
    }
  }

  fail(reason) {
    this.dispatchEvent(new CustomEvent('error', { detail: reason }));
    this.close();
  }

  // The asset's bytes: from the cache, or downloaded, checked and cached.
  fetchAsset(asset) { return cachedOrFetched(asset, () => this.download(asset)); }

  download(asset) {
    const hex = toHex(asset.hash);
    return new Promise((resolve, reject) => {
      const bytes = new Uint8Array(asset.size);
      let requested = 0, received = 0;
      const request = () => {
        while (requested < asset.size && requested - received < kRequestsAhead * kMaxChunk) {
          const length = Math.min(kMaxChunk, asset.size - requested);
          this.send({ type: 'asset-request', hash: asset.hash, offset: requested, length });
          requested += length;
        }
      };
      this.waiting.set(hex, {
        reject,
        chunk: (m) => {
          if (m.data.length === 0 || m.offset + m.data.length > asset.size) return reject(new Error(`bad chunk of ${asset.name}`));
          bytes.set(m.data, m.offset);
          received += m.data.length;
          if (received >= asset.size) {
            this.waiting.delete(hex);
            this.receivedBy.set(hex, this.bytesReceived);
            resolve(bytes);
          } else {
            request();
          }
        },
      });
      if (asset.size === 0) return resolve(bytes);
      request();
    });
  }

  chunk(m) {
    const w = this.waiting.get(toHex(m.hash));
    if (w) w.chunk(m);
  }
}

// The bytes received by the time `asset` was whole (for measuring what a view waited for).
export function bytesBy(session, asset) { return session.receivedBy.get(toHex(asset.hash)) ?? session.bytesReceived; }

export { AssetKind };
