// A product photo as the warp reads it when composing by mattes, mirroring
// client/render/tween/image_warper.cpp matte_sample() and client/viewer/turntable_view.cpp
// add_sample(): the white a photo was laid over taken out where its matte covers a pixel in
// part; colour bled outward past the outline by kBleedPixels (beyond, the floor layer as the
// photo has it); alpha the signed distance to the outline (0.5 on
// it, +-1 at kMatteRange pixels inside / outside), so it interpolates under a warp and a blend.
export const kMatteRange = 16;
// How far past the outline the object's colour is bled; further out a photo's colours are its
// floor layer on white (a shadow), kept (image_warper.hpp kBleedPixels).
export const kBleedPixels = 1.5;

// Distances from every pixel to the nearest `seed` pixel's centre, and which pixel that is
// (dead reckoning: two raster passes carrying the nearest seed, Grevera 2004).
function nearestSeeds(seed, w, h) {
  const n = w * h, dist = new Float32Array(n).fill(Infinity), near = new Int32Array(n).fill(-1);
  for (let i = 0; i < n; ++i) if (seed[i]) dist[i] = 0, near[i] = i;
  const relax = (x, y, dx, dy) => {
    const qx = x + dx, qy = y + dy;
    if (qx < 0 || qy < 0 || qx >= w || qy >= h) return;
    const s = near[qy * w + qx];
    if (s < 0) return;
    const d = Math.hypot(x - (s % w), y - Math.floor(s / w)), i = y * w + x;
    if (d < dist[i]) dist[i] = d, near[i] = s;
  };
  for (let y = 0; y < h; ++y)
    for (let x = 0; x < w; ++x) relax(x, y, -1, -1), relax(x, y, 0, -1), relax(x, y, 1, -1), relax(x, y, -1, 0);
  for (let y = h - 1; y >= 0; --y)
    for (let x = w - 1; x >= 0; --x) relax(x, y, 1, 0), relax(x, y, -1, 1), relax(x, y, 0, 1), relax(x, y, 1, 1);
  return { dist, near };
}

// `photo`: RGBA bytes of a photo laid over white; `matte`: its matte's grey bytes (RGBA, red
// used) or null (no matte: the photo is all object), of the photo's size. `scale`: a finer zoom
// level's texels per first-level pixel (SPEC T18), whose distances and bleed stay in first-level
// pixels. Returns the RGBA bytes of the warp's texture.
export function matteSample(photo, matte, w, h, scale = 1) {
  const n = w * h, out = new Uint8ClampedArray(photo);
  const alpha = new Uint8Array(n);
  for (let i = 0; i < n; ++i) {
    const a = matte ? matte[4 * i] : 255;
    alpha[i] = a;
    if (a >= 32 && a < 255) for (let c = 0; c < 3; ++c) out[4 * i + c] = Math.round((photo[4 * i + c] * 255 - (255 - a) * 255) / a);
  }
  const inside = new Uint8Array(n), outside = new Uint8Array(n);
  for (let i = 0; i < n; ++i) inside[i] = alpha[i] >= 128 ? 1 : 0, outside[i] = 1 - inside[i];
  const toObject = nearestSeeds(inside, w, h), toBackground = nearestSeeds(outside, w, h);
  const colour = new Uint8ClampedArray(out);
  for (let i = 0; i < n; ++i) {
    const a = alpha[i];
    let d = (inside[i] ? toBackground.dist[i] - 0.5 : 0.5 - toObject.dist[i]) / scale;
    if (!Number.isFinite(d)) d = inside[i] ? kMatteRange : -kMatteRange;
    if (a > 0 && a < 255 && Math.abs(d) <= 1) d = a / 255 - 0.5;
    if (a < 32 && toObject.near[i] >= 0 && toObject.dist[i] <= kBleedPixels * scale) for (let c = 0; c < 3; ++c) out[4 * i + c] = colour[4 * toObject.near[i] + c];
    out[4 * i + 3] = Math.round(Math.min(Math.max(0.5 + d / (2 * kMatteRange), 0), 1) * 255);
  }
  return out;
}

// A first-level matte's grey bytes (RGBA, red used) scaled up to a finer level's `W` x `H`
// bilinearly, as cv::resize (INTER_LINEAR) scales it for the server and the C++ client: each
// target pixel's centre mapped back into the source, clamped at the border.
export function scaledMatte(matte, w, h, W, H) {
  const out = new Uint8ClampedArray(W * H * 4);
  const sx = w / W, sy = h / H;
  for (let Y = 0; Y < H; ++Y) {
    const fy = Math.min(Math.max((Y + 0.5) * sy - 0.5, 0), h - 1), y0 = Math.floor(fy), y1 = Math.min(y0 + 1, h - 1), ty = fy - y0;
    for (let X = 0; X < W; ++X) {
      const fx = Math.min(Math.max((X + 0.5) * sx - 0.5, 0), w - 1), x0 = Math.floor(fx), x1 = Math.min(x0 + 1, w - 1), tx = fx - x0;
      const top = matte[4 * (y0 * w + x0)] * (1 - tx) + matte[4 * (y0 * w + x1)] * tx;
      const bottom = matte[4 * (y1 * w + x0)] * (1 - tx) + matte[4 * (y1 * w + x1)] * tx;
      out[4 * (Y * W + X)] = Math.round(top * (1 - ty) + bottom * ty);
    }
  }
  return out;
}
