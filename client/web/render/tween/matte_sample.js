// A product photo made ready for the warp that composes views by mattes (SPEC T14, T16), step
// for step as client/render/tween/matte_sample.cpp and common/distance_field.cpp make it: the
// two produce the same bytes (tests/golden/warp-vectors.json, written by the C++, checked by
// client/web/test/warp.test.js).
// How far from its outline a sample's alpha says inside or outside (+-1 at this many pixels).
export const kMatteRange = 16;
// How far past the outline the object's colour is bled; further out a photo's colours are its
// floor layer on white (a shadow), kept.
export const kBleedPixels = 1.5;

// Exact Euclidean distances from every pixel's centre to the nearest seed pixel's centre and
// which seed that is (y * w + x; Infinity and -1 where there is none): the nearest seed along
// each column, then along each row the lower envelope of the parabolas those make
// (Felzenszwalb & Huttenlocher), as distance_to_seeds() finds them.
export function distanceToSeeds(seed, w, h) {
  const n = w * h;
  // Each pixel's nearest seed in its column, by row (-1: none); of two as near, the one above.
  const columnSeed = new Int32Array(n).fill(-1);
  for (let x = 0; x < w; ++x) {
    let last = -1;
    for (let y = 0; y < h; ++y) {
      if (seed[y * w + x]) last = y;
      columnSeed[y * w + x] = last;
    }
    last = -1;
    for (let y = h - 1; y >= 0; --y) {
      const i = y * w + x;
      if (seed[i]) last = y;
      if (last >= 0 && (columnSeed[i] < 0 || last - y < y - columnSeed[i])) columnSeed[i] = last;
    }
  }
  const distance = new Float64Array(n).fill(Infinity), nearest = new Int32Array(n).fill(-1);
  const parabola = new Int32Array(w), from = new Float64Array(w + 1), f = new Float64Array(w);
  for (let y = 0; y < h; ++y) {
    const row = y * w;
    let k = -1;
    for (let q = 0; q < w; ++q) {
      const r = columnSeed[row + q];
      if (r < 0) continue;
      f[q] = (r - y) * (r - y);
      let s = -Infinity;
      while (k >= 0) {
        const p = parabola[k];
        s = ((f[q] + q * q) - (f[p] + p * p)) / (2 * q - 2 * p);
        if (s > from[k]) break;
        --k;
      }
      ++k;
      parabola[k] = q;
      from[k] = k === 0 ? -Infinity : s;
      from[k + 1] = Infinity;
    }
    if (k < 0) continue;
    let j = 0;
    for (let x = 0; x < w; ++x) {
      while (from[j + 1] < x) ++j;
      const q = parabola[j];
      distance[row + x] = Math.sqrt((x - q) * (x - q) + f[q]);
      nearest[row + x] = columnSeed[row + q] * w + q;
    }
  }
  return { distance, nearest };
}

// A matte's grey bytes (RGBA, red used) of `w` x `h` scaled up to `W` x `H` bilinearly, each
// pixel's centre mapped back into the matte and clamped at its border (matte_scaled_up()).
export function matteScaledUp(matte, w, h, W, H) {
  const out = new Uint8ClampedArray(W * H * 4);
  const sx = w / W, sy = h / H;
  for (let Y = 0; Y < H; ++Y) {
    const fy = Math.min(Math.max((Y + 0.5) * sy - 0.5, 0), h - 1), y0 = Math.floor(fy), y1 = Math.min(y0 + 1, h - 1), ty = fy - y0;
    for (let X = 0; X < W; ++X) {
      const fx = Math.min(Math.max((X + 0.5) * sx - 0.5, 0), w - 1), x0 = Math.floor(fx), x1 = Math.min(x0 + 1, w - 1), tx = fx - x0;
      const top = matte[4 * (y0 * w + x0)] * (1 - tx) + matte[4 * (y0 * w + x1)] * tx;
      const bottom = matte[4 * (y1 * w + x0)] * (1 - tx) + matte[4 * (y1 * w + x1)] * tx;
      const o = 4 * (Y * W + X);
      out[o] = out[o + 1] = out[o + 2] = Math.round(top * (1 - ty) + bottom * ty);
      out[o + 3] = 255;
    }
  }
  return out;
}

// A photo's RGBA bytes (`W` x `H`, laid over white) with its matte (grey bytes, RGBA, red used,
// `w` x `h`; scaled up when smaller, as a finer zoom level's first-level matte) as alpha and,
// where the matte covers a pixel in part, the white taken out again (object_on_matte()). No
// matte: the photo is all object.
export function objectOnMatte(photo, matte, w, h, W, H) {
  const out = new Uint8ClampedArray(photo);
  if (w !== W || h !== H) matte = matte && matteScaledUp(matte, w, h, W, H);
  for (let i = 0; i < W * H; ++i) {
    const a = matte ? matte[4 * i] : 255;
    out[4 * i + 3] = a;
    if (a >= 32 && a < 255)
      for (let c = 0; c < 3; ++c) out[4 * i + c] = Math.trunc((photo[4 * i + c] * 255 - (255 - a) * 255 + (a >> 1)) / a);
  }
  return out;
}

// The warp's texture of a sample from objectOnMatte(), `w` x `h` (matte_sample()): colour bled
// outward past the outline by kBleedPixels (beyond, the floor layer as the photo has it), alpha
// the signed distance to the outline (0.5 on it, +-1 at kMatteRange pixels inside / outside), so
// it interpolates under a warp and a blend. `scale`: a finer zoom level's texels per first-level
// pixel (SPEC T18), whose distances and bleed stay in first-level pixels.
export function matteSample(image, w, h, scale = 1) {
  const n = w * h, out = new Uint8ClampedArray(image);
  const inside = new Uint8Array(n), outside = new Uint8Array(n);
  for (let i = 0; i < n; ++i) inside[i] = image[4 * i + 3] >= 128 ? 1 : 0, outside[i] = 1 - inside[i];
  const toObject = distanceToSeeds(inside, w, h), toBackground = distanceToSeeds(outside, w, h);
  for (let i = 0; i < n; ++i) {
    const alpha = image[4 * i + 3];
    let d = (inside[i] ? toBackground.distance[i] - 0.5 : 0.5 - toObject.distance[i]) / scale;
    if (alpha > 0 && alpha < 255 && Math.abs(d) <= 1) d = alpha / 255 - 0.5;
    if (alpha < 32 && toObject.distance[i] <= kBleedPixels * scale)
      for (let c = 0; c < 3; ++c) out[4 * i + c] = image[4 * toObject.nearest[i] + c];
    out[4 * i + 3] = Math.round(Math.min(Math.max(0.5 + d / (2 * kMatteRange), 0), 1) * 255);
  }
  return out;
}
