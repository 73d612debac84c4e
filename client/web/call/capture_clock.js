// When each encoded voice frame was heard (SPEC F9: voice is stamped on the call's clock). An
// AudioEncoder's chunks carry timestamps of its own: Firefox ESR's counts samples from its first
// input and ignores the timestamps given after it, so every sample the capture loses (a glitch of
// the audio thread, a stalled worker) puts the stamps further behind the clock, until a listener's
// jitter rule finds every packet late; WebKitGTK's stamps a frame with its last input's time.
// Here the stamps come from the inputs themselves: the encoder's output is a run of the samples
// it was fed, so the frame that starts at the n-th sample fed was heard when the chunk holding
// that sample was, plus its place in that chunk.
export class CaptureClock {
  constructor(sampleRate) {
    this.sampleRate = sampleRate;
    this.chunks = [];  // {first (the index of its first sample among those fed), startMs, length}
    this.fedSamples = 0;
    this.emittedSamples = 0;
  }

  // A chunk of `length` samples, its first heard at `startMs`, given to the encoder.
  fed(startMs, length) {
    this.chunks.push({ first: this.fedSamples, startMs, length });
    this.fedSamples += length;
  }

  // The next encoded frame, `durationMs` long: when its first sample was heard.
  frame(durationMs) {
    const at = this.emittedSamples;
    this.emittedSamples += Math.round((durationMs * this.sampleRate) / 1000);
    while (this.chunks.length > 1 && this.chunks[0].first + this.chunks[0].length <= at) this.chunks.shift();
    const chunk = this.chunks[0];
    if (!chunk) return null;
    return chunk.startMs + ((at - chunk.first) * 1000) / this.sampleRate;
  }
}
