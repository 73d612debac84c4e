// A call's voice and connection as the page holds them (SPEC F9, F15): the page builds the audio
// graph and hands the ports over, then only shows levels and reads figures. The microphone goes
// through call/capture_worklet.js to call/call_worker.js (the WebSocket, Opus through WebCodecs),
// other members' voices come back through the worker to call/playout_worklet.js, which plays
// them on the audio clock by the jitter rule of call/playout.js. Nothing audio runs on the page's
// thread. On a cross-origin isolated page (the server's /call/ pages are) the worklets and the
// worker share rings (call/audio_ring.js) and exchange no message per chunk: then no engine routes
// a sample past the page's thread; elsewhere they pass transferred chunks through MessagePorts.
// CallLink.open() gives the element a session that lives in the worker (WorkerSession).
import { PacketRing, SampleRing } from './audio_ring.js';

const kCaptureRingFrames = 48000, kPlayoutSlots = 64, kPacketSamples = 5760;  // 1 s; 64 packets of up to 120 ms

// Why this browser cannot send or hear a call's voice, as far as the page can tell ('' when it
// can; the worker adds what only it can tell, such as WebCodecs in workers).
export function voiceUnsupported() {
  if (!globalThis.AudioWorkletNode) return 'this browser has no AudioWorklet: you will join without voice';
  if (!globalThis.Worker) return 'this browser has no Web Workers: you will join without voice';
  return '';
}

// The session as the element sees it, its socket in the worker: the same events and calls as
// net/session.js (send, fetchAsset, close; 'snapshot', 'roster', 'member-face', ...).
export class WorkerSession extends EventTarget {
  constructor(link) {
    super();
    this.link = link;
    this.requests = new Map();  // id -> {resolve, reject}
    this.nextRequest = 0;
  }

  send(message) { this.link.worker.postMessage({ op: 'send', message }); }

  fetchAsset(asset) {
    const id = ++this.nextRequest;
    return new Promise((resolve, reject) => {
      this.requests.set(id, { resolve, reject });
      this.link.worker.postMessage({ op: 'fetch-asset', id, asset });
    });
  }

  answered({ id, bytes, error }) {
    const r = this.requests.get(id);
    this.requests.delete(id);
    if (error) r?.reject(new Error(error));
    else r?.resolve(bytes);
  }

  close() {
    if (this.link.session !== this) return;
    this.link.session = null;
    this.link.worker.postMessage({ op: 'close' });
    for (const r of this.requests.values()) r.reject(new Error('left the call'));
    this.requests.clear();
  }
}

// The worker as the page talks to it: what is sent before the worker's module has loaded and
// listens is held until it says it is ready (Firefox drops messages a module worker is sent
// while its imports still load: from a page of another origin, its script is a shim importing
// the server's).
class WorkerPort {
  constructor(worker, onmessage) {
    this.worker = worker;
    this.held = [];
    worker.onmessage = (e) => {
      if (e.data.op === 'ready') this.open();
      onmessage(e.data);
    };
  }

  postMessage(message, transfer = []) {
    if (this.held) this.held.push([message, transfer]);
    else this.worker.postMessage(message, transfer);
  }

  open() {
    const held = this.held ?? [];
    this.held = null;
    for (const [message, transfer] of held) this.worker.postMessage(message, transfer);
  }

  terminate() { this.worker.terminate(); }
}

export class CallLink {
  // `onLevel(db)`: the microphone's level, ten times a second, before and during the call.
  constructor({ onLevel } = {}) {
    // A worker's script must be of the page's own origin: from a page elsewhere (the element
    // embedded on a community's site) a same-origin shim imports the server's worker module,
    // which every origin may read.
    const script = new URL('./call_worker.js', import.meta.url);
    const sameOrigin = script.origin === globalThis.location?.origin;
    const shim = sameOrigin ? null : URL.createObjectURL(new Blob([`import ${JSON.stringify(script.href)};`], { type: 'text/javascript' }));
    this.worker = new WorkerPort(new Worker(shim ?? script, { type: 'module' }), (d) => this.fromWorker(d));
    this.onLevel = onLevel;
    // Shared rings need a cross-origin isolated page (COOP and COEP).
    this.shared = !!globalThis.crossOriginIsolated && typeof SharedArrayBuffer === 'function';
    this.session = null;
    this.status = { voiceSent: 0, voiceReceived: 0, encoderErrors: 0, decoderErrors: 0 };
    this.stats = { played: 0, late: 0, skipped: 0, dropped: 0, nowMs: 0, members: new Map() };
    this.reason = new Promise((resolve) => (this.ready = resolve));
    this.audio = voiceUnsupported() ? null : this.buildAudio();
  }

  // Joins a worklet `node` to the worker as its `which` ('capture' or 'playout'): through `ring`
  // (a SharedArrayBuffer; `layout` what both need to read it) on an isolated page, else through a
  // MessagePort of their own.
  joinToWorker(node, which, ring, layout = {}) {
    if (ring) {
      node.port.postMessage({ ring, ...layout });
      this.worker.postMessage({ op: 'rings', [which]: ring, ...layout });
    } else {
      const channel = new MessageChannel();
      node.port.postMessage({ worker: channel.port1 }, [channel.port1]);
      this.worker.postMessage({ op: 'ports', [which]: channel.port2 }, [channel.port2]);
    }
  }

  // One context at Opus's 48 kHz (the worklets resample, should an engine run it at another rate).
  async buildAudio() {
    const context = (this.context = new AudioContext({ sampleRate: 48000 }));
    const base = new URL('.', import.meta.url);
    await Promise.all([context.audioWorklet.addModule(new URL('capture_worklet.js', base)), context.audioWorklet.addModule(new URL('playout_worklet.js', base))]);
    this.playout = new AudioWorkletNode(context, 'inkwire-playout', { numberOfInputs: 0, outputChannelCount: [1] });
    this.playout.connect(context.destination);
    this.playout.port.onmessage = (e) => this.fromPlayout(e.data);
    this.joinToWorker(this.playout, 'playout', this.shared && new SharedArrayBuffer(PacketRing.bytes(kPlayoutSlots, kPacketSamples)),
                      { slots: kPlayoutSlots, maxSamples: kPacketSamples });
    context.resume().catch(() => {});
    return context;
  }

  // The microphone's track into the capture worklet, whose chunks go straight to the worker.
  async capture(track) {
    const context = await this.audio;
    if (!context) return;
    let source;
    try {
      source = context.createMediaStreamSource(new MediaStream([track]));
    } catch (error) {
      throw new Error(`this browser cannot read the microphone into its audio graph (${error.message})`);
    }
    const node = new AudioWorkletNode(context, 'inkwire-capture', { numberOfOutputs: 1, outputChannelCount: [1] });
    node.port.onmessage = (e) => this.onLevel?.(e.data.level);
    this.joinToWorker(node, 'capture', this.shared && new SharedArrayBuffer(SampleRing.bytes(kCaptureRingFrames)));
    source.connect(node);
    // Pulled by the graph through a silent gain: a capture node must reach the destination to run.
    const silent = context.createGain();
    silent.gain.value = 0;
    node.connect(silent).connect(context.destination);
    this.source = source;
  }

  // A session in the worker; `clockStartMs` (performance.now() of this page) is the call clock's zero.
  open(url, session, token, name, openRoom = false) {
    this.session?.close();
    this.playout?.port.postMessage({ reset: true });
    this.clockStartMs = performance.now();
    this.session = new WorkerSession(this);
    this.worker.postMessage({ op: 'open', url, session, token, name, openRoom, clockOrigin: performance.timeOrigin + this.clockStartMs });
    this.context?.resume().catch(() => {});
    return this.session;
  }

  // The call's clock (ms since open()), shared with the worker's voice stamps.
  now() { return Math.round(performance.now() - this.clockStartMs); }

  set sending(on) { this.worker.postMessage({ op: 'sending', on }); }

  // The worker's and the playout's figures as they are now (voiceStats and status refreshed).
  // `reset`: the longest gap between packets is measured afresh from here.
  async figures(reset = false) {
    await this.audio;
    const asked = (target, message, arrived) => new Promise((resolve) => {
      this[arrived] = resolve;
      target.postMessage(message);
    });
    await Promise.all([asked(this.worker, { op: 'status', reset }, 'statusArrived'), this.playout && asked(this.playout.port, { stats: true }, 'statsArrived')]);
    return { ...this.voiceStats, ...this.status };
  }

  fromWorker(d) {
    if (d.op === 'ready') this.ready(d.reason);
    else if (d.op === 'status') {
      this.status = d;
      this.statusArrived?.();
      this.statusArrived = null;
    }
    else if (d.op === 'asset') this.session?.answered(d);
    else if (d.op === 'event') this.session?.dispatchEvent(new CustomEvent(d.type, { detail: d.detail }));
  }

  fromPlayout(d) {
    if (d.stats) {
      this.stats = { ...d.stats, members: new Map(d.stats.members), at: performance.now() };
      this.statsArrived?.();
      this.statsArrived = null;
    }
    if (d.recording) this.recordingArrived?.({ sampleRate: d.sampleRate, samples: d.recording });
  }

  // What this member heard: {played, late, dropped, delayMs, skipped} (delayMs the largest member's
  // delay; skipped the packets not played as a member's offset caught up with its quickest).
  get voiceStats() {
    const delays = [...this.stats.members.values()].map((m) => m.delayMs);
    const { played, late, dropped, skipped } = this.stats;
    return { played, late, dropped, delayMs: delays.length ? Math.max(...delays) : 0, skipped };
  }

  // When `member`'s moment `timeMs` plays, in this page's performance.now() ms; null before its voice.
  localTime(member, timeMs) {
    const m = this.stats.members.get(member);
    if (!m || !this.context) return null;
    return performance.now() + (timeMs + m.offsetMs + m.delayMs - this.context.currentTime * 1000);
  }

  // Tests listen to what was played: record() from now, then recording() gives it (mono).
  async record() {
    await this.audio;
    this.playout?.port.postMessage({ record: true });
  }
  async recording() {
    await this.audio;
    if (!this.playout) return { sampleRate: 48000, samples: new Float32Array() };
    return new Promise((resolve) => {
      this.recordingArrived = resolve;
      this.playout.port.postMessage({ recording: true });
    });
  }

  close() {
    this.session?.close();
    this.worker.terminate();
    this.source?.disconnect();
    this.context?.close();
  }
}
