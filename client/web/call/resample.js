// Mono samples from one rate to another by linear interpolation: the call's Opus runs at 48 kHz,
// and an engine whose audio runs at another rate (a 44.1 kHz device) meets it here, in both
// worklets. Speech loses nothing a listener hears at these ratios.
export function resampled(samples, from, to) {
  if (from === to) return samples;
  const out = new Float32Array(Math.max(1, Math.round((samples.length * to) / from)));
  const step = from / to;
  for (let i = 0; i < out.length; ++i) {
    const x = i * step, k = Math.floor(x), f = x - k;
    const a = samples[Math.min(k, samples.length - 1)], b = samples[Math.min(k + 1, samples.length - 1)];
    out[i] = a + (b - a) * f;
  }
  return out;
}
