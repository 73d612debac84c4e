// A call's voice in the browser (SPEC F9), mirroring client/call/voice_codec.cpp and
// call_audio.cpp: the microphone's frames (MediaStreamTrackProcessor, 48 kHz) encoded as mono
// Opus packets by WebCodecs' AudioEncoder, and every member's packets decoded by an
// AudioDecoder each and played through one AudioContext at their member's moment: each
// member's clock is mapped to this page's by its first packet plus a jitter delay that a late
// packet raises (playoutMs, as client/call/playout_delay.hpp), a packet later than the largest
// delay is dropped, and the same mapping says when a face code is due (lip sync).

export const kStartDelayMs = 80, kDelayMarginMs = 20, kMaxDelayMs = 300;

// Where a packet stamped `timeMs` on its member's clock plays on this one (ms), given `offsetMs`
// (this clock minus the member's, from its first packet), `member.delayMs` (raised here when the
// packet is late) and `nowMs`, how far this clock has played: null when the packet is later than
// even the largest delay allows. The C++ rule, operation for operation (golden "playout").
export function playoutMs(timeMs, offsetMs, member, nowMs) {
  const at = timeMs + offsetMs + member.delayMs;
  if (at >= nowMs) return at;
  const raised = member.delayMs + (nowMs - at) + kDelayMarginMs;
  if (raised > kMaxDelayMs) return null;
  member.delayMs = raised;
  return timeMs + offsetMs + member.delayMs;
}

// Why this browser cannot send or hear a call's voice, or '' when it can.
export function voiceUnsupported() {
  if (!globalThis.AudioEncoder || !globalThis.AudioDecoder) return 'this browser has no WebCodecs audio (AudioEncoder/AudioDecoder)';
  if (!globalThis.MediaStreamTrackProcessor) return 'this browser cannot read microphone frames (MediaStreamTrackProcessor)';
  return '';
}

// The microphone: its level always (a meter), its Opus packets while `sending`.
export class VoiceSender {
  constructor(track, { bitrate = 10000, frameMs = 60, onPacket, onLevel } = {}) {  // as client/call/publisher.hpp
    this.onPacket = onPacket;
    this.onLevel = onLevel;
    this.sending = false;
    this.frameMs = frameMs;
    this.encoder = new AudioEncoder({
      output: (chunk) => {
        const bytes = new Uint8Array(chunk.byteLength);
        chunk.copyTo(bytes);
        if (this.sending) this.onPacket?.(bytes, chunk.timestamp);
      },
      error: (e) => console.warn('voice encoder:', e.message),
    });
    this.configured = false;
    this.bitrate = bitrate;
    this.reader = new MediaStreamTrackProcessor({ track }).readable.getReader();
    this.pump();
  }

  async pump() {
    for (;;) {
      let result;
      try {
        result = await this.reader.read();
      } catch {
        return;
      }
      if (result.done) return;
      const frame = result.value;
      const samples = new Float32Array(frame.numberOfFrames);
      frame.copyTo(samples, { planeIndex: 0, format: 'f32-planar' });
      let sum = 0;
      for (const s of samples) sum += s * s;
      this.onLevel?.(10 * Math.log10(Math.max(sum / Math.max(samples.length, 1), 1e-10)));
      if (!this.configured) {
        this.encoder.configure({ codec: 'opus', sampleRate: frame.sampleRate, numberOfChannels: 1, bitrate: this.bitrate,
                                 opus: { frameDuration: this.frameMs * 1000, complexity: 5 } });
        this.configured = true;
      }
      // Mono from the first channel, whatever the device gives.
      const mono = new AudioData({ format: 'f32-planar', sampleRate: frame.sampleRate, numberOfFrames: frame.numberOfFrames,
                                   numberOfChannels: 1, timestamp: frame.timestamp, data: samples });
      frame.close();
      if (this.encoder.state === 'configured') this.encoder.encode(mono);
      mono.close();
    }
  }

  stop() {
    this.reader.cancel().catch(() => {});
    if (this.encoder.state !== 'closed') this.encoder.close();
  }
}

// Every member's voice, decoded and scheduled on one AudioContext.
export class VoicePlayer {
  constructor() {
    this.context = new AudioContext({ sampleRate: 48000 });
    this.members = new Map();  // member -> {decoder, offsetMs (context ms - member ms), delayMs, pending}
    this.late = 0;
    this.played = 0;
    this.recorded = [];        // [{at (context seconds), samples}]: what was played, for measuring
  }

  resume() { return this.context.resume(); }

  add(frame) {
    let m = this.members.get(frame.member);
    if (!m) {
      m = { offsetMs: this.context.currentTime * 1000 - frame.time_ms, delayMs: kStartDelayMs, decoder: null, pending: [] };
      m.decoder = new AudioDecoder({
        output: (data) => this.play(m, data),
        error: (e) => console.warn('voice decoder:', e.message),
      });
      m.decoder.configure({ codec: 'opus', sampleRate: 48000, numberOfChannels: 1 });
      this.members.set(frame.member, m);
    }
    m.pending.push(frame.time_ms);  // placed when decoded, on the clock as it is then
    m.decoder.decode(new EncodedAudioChunk({ type: 'key', timestamp: frame.time_ms * 1000, data: frame.opus }));
  }

  play(m, data) {
    const timeMs = m.pending.shift();
    const atMs = timeMs === undefined ? null : playoutMs(timeMs, m.offsetMs, m, this.context.currentTime * 1000);
    const samples = new Float32Array(data.numberOfFrames);
    data.copyTo(samples, { planeIndex: 0, format: 'f32-planar' });
    const buffer = this.context.createBuffer(1, samples.length, data.sampleRate);
    buffer.copyToChannel(samples, 0);
    data.close();
    if (atMs === null) {
      ++this.late;
      return;
    }
    const at = atMs / 1000;
    const source = this.context.createBufferSource();
    source.buffer = buffer;
    source.connect(this.context.destination);
    source.start(at);
    ++this.played;
    this.recorded.push({ at, samples });
  }

  // When `member`'s moment `timeMs` plays, in performance.now() milliseconds; null before its voice.
  localTime(member, timeMs) {
    const m = this.members.get(member);
    if (!m) return null;
    const contextSeconds = (timeMs + m.offsetMs + m.delayMs) / 1000;
    return performance.now() + (contextSeconds - this.context.currentTime) * 1000;
  }

  // Everything played so far mixed into one track (48 kHz) from the first sound on: for tests.
  recording() {
    if (!this.recorded.length) return { sampleRate: 48000, samples: new Float32Array() };
    const start = Math.min(...this.recorded.map((r) => r.at));
    const end = Math.max(...this.recorded.map((r) => r.at + r.samples.length / 48000));
    const out = new Float32Array(Math.ceil((end - start) * 48000));
    for (const r of this.recorded) {
      const at = Math.round((r.at - start) * 48000);
      for (let i = 0; i < r.samples.length && at + i < out.length; ++i) out[at + i] += r.samples[i];
    }
    return { sampleRate: 48000, samples: out };
  }

  close() {
    for (const m of this.members.values()) if (m.decoder.state !== 'closed') m.decoder.close();
    this.context.close();
  }
}
