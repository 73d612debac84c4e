// A call member's connection and voice, off the page's thread (SPEC F15): this
// dedicated worker holds the call's WebSocket (net/session.js), encodes the microphone's chunks
// (from call/capture_worklet.js) to Opus with WebCodecs' AudioEncoder and sends them, and decodes
// every member's voice with an AudioDecoder each, handing the samples to call/playout_worklet.js.
// Voice never passes through the page, so a page whose thread stalls, or a hidden tab, keeps
// talking and listening. Everything else the session says goes to the page as it arrives; what
// the page sends comes through here.
//
// From the page: {op: 'ports', capture, playout} (MessagePorts to the worklets) or, on a
// cross-origin isolated page, {op: 'rings', capture, playout, slots, maxSamples} (the shared
// rings of call/audio_ring.js: no message at all per chunk), {op: 'open', url,
// session, token, name, clockOrigin}, {op: 'send', message}, {op: 'sending', on}, {op:
// 'fetch-asset', id, asset}, {op: 'close'}, {op: 'cut'} (the socket closed as a lost network would,
// for tests), {op: 'status'} (answered at once). To the page: {op: 'ready', reason} once, {op:
// 'event', type, detail} for the session's events, {op: 'asset', id, bytes | error}, and
// {op: 'status', voiceSent, voiceReceived, voiceGapMs, encoderErrors, decoderErrors, ringFull}
// twice a second.
import { Session } from '../net/session.js';
import { FrameReader } from '../protocol/messages.js';
import { PacketRing, SampleRing } from './audio_ring.js';
import { CaptureClock } from './capture_clock.js';

const kOpusRate = 48000, kBitrate = 10000, kFrameMs = 60;  // as client/call/publisher.hpp
const kForwarded = ['snapshot', 'roster', 'member-layers', 'member-face', 'face-region', 'key-frame-request', 'permissions', 'state', 'refused', 'error',
                    'close', 'host-key', 'shut-out'];

let session = null, joined = false, sending = false, clockOrigin = 0, encoding = null, playout = null, playoutRing = null, route = null;
const decoders = new Map();  // member -> {decoder, pending: [time_ms]}
// voiceGapMs: the longest wait between two voice packets arriving here (what the network and this
// engine's worker added; the playout's delay must cover it).
// voiceRoute: how voice arrives, 'websocket' or 'stream' (the voice route's fetch).
const status = { voiceSent: 0, voiceReceived: 0, voiceGapMs: 0, encoderErrors: 0, decoderErrors: 0, ringFull: 0, voiceRoute: 'websocket' };
let lastVoiceAt = 0;

const callClockMs = () => performance.timeOrigin + performance.now() - clockOrigin;

// Why this engine cannot carry a call's voice in a worker, or ''.
async function voiceReason() {
  if (!self.AudioEncoder || !self.AudioDecoder) return 'this browser has no WebCodecs audio in workers (AudioEncoder, AudioDecoder): you will join without voice';
  const config = { codec: 'opus', sampleRate: kOpusRate, numberOfChannels: 1, bitrate: kBitrate };
  try {
    const [encode, decode] = await Promise.all([AudioEncoder.isConfigSupported(config), AudioDecoder.isConfigSupported({ codec: 'opus', sampleRate: kOpusRate, numberOfChannels: 1 })]);
    if (!encode.supported || !decode.supported) return 'this browser cannot encode or decode Opus (WebCodecs): you will join without voice';
  } catch (error) {
    return `this browser refuses Opus in WebCodecs (${error.message}): you will join without voice`;
  }
  return '';
}

function makeEncoder() {
  const heardAt = new CaptureClock(kOpusRate);
  const e = new AudioEncoder({
    output: (chunk) => {
      // Each chunk is one frame of the duration configured: WebKitGTK 2.50 says 20 ms of every
      // 60 ms chunk (the last input's), so its own duration is not trusted either.
      const timeMs = heardAt.frame(kFrameMs);
      if (!sending || !joined || !session || timeMs === null) return;
      const opus = new Uint8Array(chunk.byteLength);
      chunk.copyTo(opus);
      // Stamped on the call's clock with when its first sample was heard (the capture's time).
      session.send({ type: 'voice-frame', member: 0, time_ms: Math.max(0, Math.round(timeMs)), opus });
      ++status.voiceSent;
    },
    error: () => {
      ++status.encoderErrors;
      encoding = null;  // made again for the next chunk
    },
  });
  e.configure({ codec: 'opus', sampleRate: kOpusRate, numberOfChannels: 1, bitrate: kBitrate, opus: { frameDuration: kFrameMs * 1000, complexity: 5 } });
  return { encoder: e, heardAt };
}

// The capture worklet's shared ring, read every 10 ms: each 20 ms chunk stamped back from now.
function readCaptureRing(ring) {
  const kChunkMs = 20, chunk = (kOpusRate * kChunkMs) / 1000;
  setInterval(() => {
    const chunks = [];
    for (let samples; (samples = ring.read(chunk, chunk)); ) chunks.push(samples);
    const now = callClockMs();
    chunks.forEach((samples, i) => captured({ samples, sampleRate: kOpusRate }, now - (chunks.length - 1 - i) * kChunkMs));
  }, 10);
}

// A chunk of the microphone, heard until `endMs` on the call's clock (now, when not given).
function captured({ samples, sampleRate }, endMs = callClockMs()) {
  if (!sending || !joined) return;
  encoding ??= makeEncoder();
  const startMs = endMs - (samples.length / sampleRate) * 1000;
  const data = new AudioData({ format: 'f32-planar', sampleRate, numberOfFrames: samples.length, numberOfChannels: 1,
                               timestamp: Math.max(0, Math.round(startMs * 1000)), data: samples });
  if (encoding.encoder.state === 'configured') {
    encoding.encoder.encode(data);
    encoding.heardAt.fed(startMs, samples.length);  // at kOpusRate, as the worklet resampled it
  }
  data.close();
}

function heard(frame) {
  ++status.voiceReceived;
  const now = performance.now();
  if (lastVoiceAt) status.voiceGapMs = Math.max(status.voiceGapMs, Math.round(now - lastVoiceAt));
  lastVoiceAt = now;
  let m = decoders.get(frame.member);
  if (!m) {
    m = { pending: [] };
    m.decoder = new AudioDecoder({
      output: (data) => {
        const timeMs = m.pending.shift();
        const samples = new Float32Array(data.numberOfFrames);
        data.copyTo(samples, { planeIndex: 0, format: 'f32-planar' });
        data.close();
        if (timeMs === undefined) return;
        if (playoutRing) {
          if (!playoutRing.push(frame.member, timeMs, samples)) ++status.ringFull;
        } else {
          playout?.postMessage({ member: frame.member, timeMs, samples }, [samples.buffer]);
        }
      },
      error: () => {
        ++status.decoderErrors;
        decoders.delete(frame.member);  // made again from the member's next packet
      },
    });
    m.decoder.configure({ codec: 'opus', sampleRate: kOpusRate, numberOfChannels: 1 });
    decoders.set(frame.member, m);
  }
  if (m.decoder.state !== 'configured') return;
  m.pending.push(frame.time_ms);
  m.decoder.decode(new EncodedAudioChunk({ type: 'key', timestamp: frame.time_ms * 1000, data: frame.opus }));
}

// The call's voice by its second route (protocol/SPEC.md "Voice route"): one streamed fetch of
// framed voice packets. Gecko hands a worker's fetch body to the worker without the page's
// thread, which it does not do for a worker's WebSocket: a busy page then stalls nothing here.
// If the route fails or ends, the server sends voice on the WebSocket again.
async function listenByRoute(s, url, ticket) {
  route?.abort();
  const abort = (route = new AbortController());
  try {
    const response = await fetch(new URL(`/voice/${ticket}`, url.replace(/^ws/, 'http')), { cache: 'no-store', signal: abort.signal });
    if (!response.ok || !response.body) return;
    status.voiceRoute = 'stream';
    const reader = response.body.getReader(), frames = new FrameReader();
    for (;;) {
      const { done, value } = await reader.read();
      if (done || session !== s) break;
      frames.feed(value);
      s.lastHeard = performance.now();  // word from the server, as on its socket
      for (let m; (m = frames.next()); ) if (m.type === 'voice-frame') heard(m);
    }
  } catch {
    // aborted, refused, or malformed: the WebSocket carries voice again
  } finally {
    if (route === abort) route = null, status.voiceRoute = 'websocket';
    abort.abort();
  }
}

function open({ url, session: name, token, name: member, clockOrigin: origin, openRoom }) {
  close();
  clockOrigin = origin;
  const s = (session = new Session(url, name, token, member, { openRoom }));
  for (const type of kForwarded)
    s.addEventListener(type, (e) => {
      if (session !== s) return;
      if (type === 'snapshot') joined = true;
      if (type === 'close') joined = false;
      self.postMessage({ op: 'event', type, detail: e.detail });
    });
  s.addEventListener('voice-frame', (e) => heard(e.detail));
  s.addEventListener('voice-route', (e) => listenByRoute(s, url, e.detail.ticket));
}

function close() {
  if (session) {
    try { session.send({ type: 'leave' }); } catch {}
    session.close();
  }
  session = null;
  joined = false;
  route?.abort();
  for (const m of decoders.values()) if (m.decoder.state !== 'closed') m.decoder.close();
  decoders.clear();
}

async function fetchAsset({ id, asset }) {
  try {
    if (!session) throw new Error('not in a call');
    const bytes = await session.fetchAsset(asset);
    self.postMessage({ op: 'asset', id, bytes });
  } catch (error) {
    self.postMessage({ op: 'asset', id, error: error.message });
  }
}

self.onmessage = (e) => {
  const d = e.data;
  if (d.op === 'ports') {
    if (d.capture) d.capture.onmessage = (m) => captured(m.data);
    playout = d.playout ?? playout;
  } else if (d.op === 'rings') {
    if (d.capture) readCaptureRing(new SampleRing(d.capture));
    if (d.playout) playoutRing = new PacketRing(d.playout, d.slots, d.maxSamples);
  } else if (d.op === 'open') open(d);
  else if (d.op === 'send') session?.send(d.message);
  else if (d.op === 'sending') sending = d.on;
  else if (d.op === 'fetch-asset') fetchAsset(d);
  else if (d.op === 'close') close();
  else if (d.op === 'cut') session?.socket.close();  // what a lost network does to the socket, without a leave (tests)
  else if (d.op === 'status') {
    self.postMessage({ op: 'status', ...status });
    if (d.reset) status.voiceGapMs = 0;
  }
};

setInterval(() => self.postMessage({ op: 'status', ...status }), 500);
voiceReason().then((reason) => self.postMessage({ op: 'ready', reason }));
