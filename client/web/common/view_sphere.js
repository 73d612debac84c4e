// Where a view direction falls among a product's cells, mirroring common/tween/view_sphere.cpp
// locate_view(): the cell, and the weight of each of its samples. For a pair, the angle
// fraction t of the view projected onto the pair's great circle; for a triangle, the
// barycentric coordinates of the view ray through the triangle's plane; `inside` when the view
// lies within its cell (not past the end of an open ring or above the top row).
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const normalize = (a) => { const l = norm(a); return [a[0] / l, a[1] / l, a[2] / l]; };
const angleBetween = (a, b) => Math.atan2(norm(cross(a, b)), dot(a, b));
const kInside = 1e-3;  // radians past a pair's end, or barycentric weight below 0, still inside

// `cells`: [{samples: [...]}, ...] (null for cells not there yet); `directions`: per sample.
export function locateView(directions, cells, direction) {
  const d = normalize(direction);
  const best = { cell: -1, t: 0, weights: [1, 0, 0], inside: false };
  let bestMiss = 1e9;
  cells.forEach((cell, i) => {
    if (!cell) return;
    if (cell.samples.length === 2) {
      const a = normalize(directions[cell.samples[0]]), b = normalize(directions[cell.samples[1]]);
      let n = cross(a, b);
      if (norm(n) < 1e-6) return;
      n = normalize(n);
      let inPlane = d.map((c, k) => c - dot(d, n) * n[k]);
      if (norm(inPlane) < 1e-6) return;
      inPlane = normalize(inPlane);
      const total = angleBetween(a, b);
      const theta = Math.atan2(dot(cross(a, inPlane), n), dot(a, inPlane));
      const outside = Math.max(0, -theta, theta - total);
      const miss = outside + Math.abs(dot(d, n)) * 1e-3;  // prefer the ring the view is nearest
      if (miss < bestMiss) {
        bestMiss = miss;
        best.inside = outside <= kInside;
        best.cell = i;
        best.t = Math.min(Math.max(theta / total, 0), 1);
        best.weights = [1 - best.t, best.t, 0];
      }
    } else {
      const [a, b, c] = cell.samples.map((s) => normalize(directions[s]));
      // Solve w0 a + w1 b + w2 c = d (Cramer's rule).
      const det = dot(a, cross(b, c));
      if (Math.abs(det) < 1e-9) return;
      let w = [dot(d, cross(b, c)) / det, dot(a, cross(d, c)) / det, dot(a, cross(b, d)) / det];
      const sum = w[0] + w[1] + w[2];
      if (sum <= 0) return;
      w = w.map((x) => x / sum);
      const miss = Math.max(0, -w[0], -w[1], -w[2]);
      if (miss < bestMiss) {
        bestMiss = miss;
        best.inside = miss <= kInside;
        best.cell = i;
        w = w.map((x) => Math.max(x, 0));
        const s = w[0] + w[1] + w[2];
        best.weights = w.map((x) => x / s);
        best.t = 0;
      }
    }
  });
  return best;
}

// How near a sample's direction lies to a view direction: the cosine of their angle times the
// view direction's length (the same for every sample). Step for step as the C++
// (common/tween/view_sphere.cpp nearness()), so both pick the same sample on a tie.
export function nearness(sample, direction) {
  const [x, y, z] = sample;
  return (x * direction[0] + y * direction[1] + z * direction[2]) / Math.sqrt(x * x + y * y + z * z);
}

// The sample nearest `direction` among those `usable(i)` allows (every one without it), the first
// on a tie; -1 when none is.
export function nearestSample(directions, direction, usable) {
  let best = -1, bestNearness = 0;
  directions.forEach((d, i) => {
    if (usable && !usable(i)) return;
    const n = nearness(d, direction);
    if (best < 0 || n > bestNearness) best = i, bestNearness = n;
  });
  return best;
}

// The samples a view from `direction` is drawn from once they are there: its cell's when it lies
// inside one, and the nearest (view_sphere.cpp view_samples()).
export function viewSamples(directions, cells, direction) {
  const at = locateView(directions, cells, direction);
  const out = at.cell >= 0 && at.inside ? [...cells[at.cell].samples] : [];
  const nearest = nearestSample(directions, direction);
  if (nearest >= 0 && !out.includes(nearest)) out.push(nearest);
  return out;
}
