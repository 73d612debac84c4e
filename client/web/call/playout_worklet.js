// Every member's voice played on the audio thread (SPEC F15): decoded 48 kHz chunks come from the
// call's worker through a shared ring (call/audio_ring.js) when the page is cross-origin isolated,
// else through a MessagePort, and are mixed into a ring at the frame the jitter rule
// (call/playout.js, pinned to the C++) gives on the audio clock itself; each render quantum reads
// its frames out of the ring and clears them. Nothing here waits on the page's thread, so a
// stalled page or a hidden tab keeps hearing. The page is told, four times a second, what was
// played, too late, skipped or dropped and each member's clock offset and delay (lip sync,
// voiceStats), and how much sooner than its first packet any later one came (a slow start);
// on request it is sent those figures at once, or what was played since the first voice (tests listen to it).
import { PacketRing } from './audio_ring.js';
import { placeVoice, voiceClock } from './playout.js';
import { resampled } from './resample.js';

const kRingSeconds = 2, kStatsEveryMs = 250, kOpusRate = 48000, kMaxRecordingSeconds = 120;

class PlayoutProcessor extends AudioWorkletProcessor {
  constructor() {
    super();
    this.mix = new Float32Array(sampleRate * kRingSeconds);  // indexed by frame modulo its length
    this.members = new Map();  // member -> its voiceClock (call/playout.js), firstMs, earliestMs
    this.played = this.late = this.skipped = this.dropped = 0;
    this.lastStats = 0;
    this.recording = null;     // [Float32Array] since the first voice, while asked
    this.port.onmessage = (e) => this.command(e.data);
  }

  command(d) {
    if (d.worker) d.worker.onmessage = (e) => this.packet(e.data);
    if (d.ring) this.packets = new PacketRing(d.ring, d.slots, d.maxSamples);
    if (d.record !== undefined) this.recording = d.record ? [] : null;
    if (d.stats) this.postStats();
    if (d.reset) {
      this.members.clear();
      this.mix.fill(0);
    }
    if (d.recording) {
      const parts = this.recording ?? [], out = new Float32Array(parts.reduce((n, p) => n + p.length, 0));
      let at = 0;
      for (const p of parts) out.set(p, (at += p.length) - p.length);
      this.port.postMessage({ recording: out, sampleRate }, [out.buffer]);
      if (this.recording) this.recording = [];
    }
  }

  nowMs() { return (currentFrame / sampleRate) * 1000; }

  packet({ member, timeMs, samples }) {
    const nowMs = this.nowMs();
    let m = this.members.get(member);
    if (!m) this.members.set(member, (m = { ...voiceClock(), firstMs: nowMs - timeMs }));
    m.earliestMs = Math.min(m.earliestMs ?? Infinity, nowMs - timeMs - m.firstMs);  // how much sooner than the first a packet came
    const placed = placeVoice(timeMs, (samples.length / kOpusRate) * 1000, nowMs, nowMs, m);
    if (placed.kind === 'late') {
      ++this.late;
      return;
    }
    if (placed.kind === 'skip') {
      ++this.skipped;
      return;
    }
    const mine = resampled(samples, kOpusRate, sampleRate), skip = Math.round((placed.skipMs / 1000) * sampleRate);
    const start = Math.round((placed.atMs / 1000) * sampleRate), length = this.mix.length;
    if (start + mine.length - skip > currentFrame + length) {
      ++this.dropped;  // further ahead than the mix holds: a member's clock that jumped
      return;
    }
    for (let i = skip; i < mine.length; ++i) this.mix[(start + i - skip) % length] += mine[i];
    ++this.played;
    if (this.recording && !this.recording.started) this.recording.started = true;
  }

  process(inputs, outputs) {
    this.packets?.drain((member, timeMs, samples) => this.packet({ member, timeMs, samples }));
    const out = outputs[0], first = out[0], length = this.mix.length;
    for (let i = 0; i < first.length; ++i) {
      const k = (currentFrame + i) % length;
      first[i] = this.mix[k];
      this.mix[k] = 0;
    }
    for (let c = 1; c < out.length; ++c) out[c].set(first);
    if (this.recording?.started && this.recording.length < (kMaxRecordingSeconds * sampleRate) / first.length) this.recording.push(first.slice());
    if (this.nowMs() - this.lastStats >= kStatsEveryMs) this.postStats();
    return true;
  }

  postStats() {
    const nowMs = (this.lastStats = this.nowMs());
    this.port.postMessage({ stats: { played: this.played, late: this.late, skipped: this.skipped, dropped: this.dropped, nowMs, members: [...this.members] } });
  }
}

registerProcessor('inkwire-playout', PlayoutProcessor);
