// The microphone on the audio thread (SPEC F15): an AudioWorkletProcessor, the one portable way to
// read microphone samples (Firefox and Safari have no MediaStreamTrackProcessor for audio). The
// first channel goes, in 20 ms chunks at 48 kHz, straight to the call's worker through a shared
// ring (call/audio_ring.js) when the page is cross-origin isolated, else through a MessagePort the
// page hands over once: the page's own thread never touches a sample, so a busy
// page cannot delay or lose the voice. The page only hears the level, ten times a second.
import { SampleRing } from './audio_ring.js';
import { resampled } from './resample.js';

const kOpusRate = 48000, kChunkMs = 20, kLevelEveryMs = 100;

class CaptureProcessor extends AudioWorkletProcessor {
  constructor() {
    super();
    this.worker = null;
    this.chunkFrames = Math.round((sampleRate * kChunkMs) / 1000);
    this.chunk = new Float32Array(this.chunkFrames);
    this.filled = 0;
    this.energy = 0;
    this.energyFrames = 0;
    this.port.onmessage = (e) => {
      if (e.data.worker) this.worker = e.data.worker;
      if (e.data.ring) this.ring = new SampleRing(e.data.ring);
    };
  }

  process(inputs) {
    const input = inputs[0]?.[0];
    if (!input) return true;
    for (let i = 0; i < input.length; ++i) {
      this.chunk[this.filled++] = input[i];
      this.energy += input[i] * input[i];
      if (this.filled === this.chunkFrames) this.flush();
    }
    this.energyFrames += input.length;
    if (this.energyFrames >= (sampleRate * kLevelEveryMs) / 1000) {
      this.port.postMessage({ level: 10 * Math.log10(Math.max(this.energy / this.energyFrames, 1e-10)) });
      this.energy = this.energyFrames = 0;
    }
    return true;
  }

  flush() {
    const samples = resampled(this.chunk, sampleRate, kOpusRate);
    if (this.ring) this.ring.write(samples);
    else this.worker?.postMessage({ samples, sampleRate: kOpusRate }, [samples.buffer]);
    this.chunk = new Float32Array(this.chunkFrames);
    this.filled = 0;
  }
}

registerProcessor('inkwire-capture', CaptureProcessor);
