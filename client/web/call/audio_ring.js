// Wait-free single-producer, single-consumer rings in SharedArrayBuffers (after
// padenot's ringbuf.js): how the call's worker and its audio worklets hand each other sound
// without a message, so nothing waits on any other thread. Available when the page is
// cross-origin isolated (the server sends /call/ pages with COOP and COEP); elsewhere the
// worklets and the worker exchange transferred chunks instead (call/voice.js).
// Counters are frames or packets since the start, kept in Int32 slots by Atomics; they wrap
// after 2^31, half a day of sound, and are compared by their difference.

const slot = (counter, size) => ((counter % size) + size) % size;

// Mono samples, the capture's direction (worklet -> worker).
export class SampleRing {
  static bytes(frames) { return 8 + 4 * frames; }

  constructor(buffer) {
    this.counters = new Int32Array(buffer, 0, 2);  // [written, read]
    this.data = new Float32Array(buffer, 8);
  }

  // What does not fit is dropped (a reader that stopped); returns how many were written.
  write(samples) {
    const written = Atomics.load(this.counters, 0), read = Atomics.load(this.counters, 1), size = this.data.length;
    const n = Math.min(samples.length, size - ((written - read) | 0));
    for (let i = 0; i < n; ++i) this.data[slot(written + i, size)] = samples[i];
    Atomics.store(this.counters, 0, (written + n) | 0);
    return n;
  }

  // Up to `max` samples written and not yet read, or null when there are fewer than `min`.
  read(min, max) {
    const written = Atomics.load(this.counters, 0), read = Atomics.load(this.counters, 1), size = this.data.length;
    const available = (written - read) | 0;
    if (available < min) return null;
    const out = new Float32Array(Math.min(available, max));
    for (let i = 0; i < out.length; ++i) out[i] = this.data[slot(read + i, size)];
    Atomics.store(this.counters, 1, (read + out.length) | 0);
    return out;
  }
}

// Decoded voice packets, the playout's direction (worker -> worklet): {member, timeMs, samples}
// in fixed slots of up to `maxSamples` each.
export class PacketRing {
  static bytes(slots, maxSamples) { return 8 + slots * (24 + 4 * maxSamples); }

  constructor(buffer, slots, maxSamples) {
    this.counters = new Int32Array(buffer, 0, 2);  // [written, read]
    this.headers = new Float64Array(buffer, 8, 3 * slots);  // member, timeMs, length
    this.data = new Float32Array(buffer, 8 + 24 * slots, slots * maxSamples);
    this.slots = slots;
    this.maxSamples = maxSamples;
  }

  // False when every slot is full (the reader has stopped) or the packet is too long.
  push(member, timeMs, samples) {
    const written = Atomics.load(this.counters, 0), read = Atomics.load(this.counters, 1);
    if (((written - read) | 0) >= this.slots || samples.length > this.maxSamples) return false;
    const at = slot(written, this.slots);
    this.headers.set([member, timeMs, samples.length], 3 * at);
    this.data.set(samples, at * this.maxSamples);
    Atomics.store(this.counters, 0, (written + 1) | 0);
    return true;
  }

  // Each packet written and not yet read, oldest first, to `take(member, timeMs, samples)`.
  drain(take) {
    const written = Atomics.load(this.counters, 0);
    let read = Atomics.load(this.counters, 1);
    for (; read !== written; read = (read + 1) | 0) {
      const at = slot(read, this.slots), [member, timeMs, length] = this.headers.subarray(3 * at, 3 * at + 3);
      take(member, timeMs, this.data.subarray(at * this.maxSamples, at * this.maxSamples + length));
    }
    Atomics.store(this.counters, 1, read);
  }
}
