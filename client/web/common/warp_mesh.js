// The triangulated control points a warp draws, mirroring common/tween/warp_mesh.cpp: the
// cell's points plus fixed points along the image border, Delaunay triangles on the pairs'
// halfway positions (triangles' centroids), points within 1/8 pixel of an earlier one left out.
// tests/golden/warp-vectors.json, written by the C++, pins the two to the same triangles.

// Border points every quarter side, corners included, the same in every sample.
export function borderPoints(width, height, perSide = 4) {
  const out = [];
  for (let i = 0; i < perSide; ++i) {
    const f = i / perSide;
    out.push([f * width, 0], [width, f * height], [(1 - f) * width, height], [0, (1 - f) * height]);
  }
  return out;
}

const kNearSquared = 0.125 * 0.125;

// Written as delaunay_triangles() in warp_mesh.cpp writes it, operation for operation, so both
// round alike and pick the same triangles where four points lie on one circle.
function circumcircle(a, b, c) {
  const [ax, ay] = a, [bx, by] = b, [cx, cy] = c;
  const d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
  const x = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d;
  const y = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d;
  return { x, y, r2: (ax - x) * (ax - x) + (ay - y) * (ay - y) };
}

// Delaunay triangles of `points` ([x, y] each) as index triples (Bowyer-Watson). Points closer
// than 1/8 pixel to an earlier one are left out of the triangles (they would fold).
export function delaunayTriangles(points) {
  if (points.length < 3) return [];
  const kept = [];
  for (let i = 0; i < points.length; ++i) {
    const near = kept.some((j) => {
      const dx = points[j][0] - points[i][0], dy = points[j][1] - points[i][1];
      return dx * dx + dy * dy < kNearSquared;
    });
    if (!near) kept.push(i);
  }
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const i of kept) {
    minX = Math.min(minX, points[i][0]), maxX = Math.max(maxX, points[i][0]);
    minY = Math.min(minY, points[i][1]), maxY = Math.max(maxY, points[i][1]);
  }
  // From a triangle far round them all, whose corners are left out at the end.
  const span = Math.max(maxX - minX, maxY - minY, 1) * 20, cx = (minX + maxX) / 2, cy = (minY + maxY) / 2;
  const all = points.map((p) => [p[0], p[1]]);
  const corner = all.length;
  all.push([cx - span, cy - span], [cx + span, cy - span], [cx, cy + span]);
  const make = (a, b, c) => ({ v: [a, b, c], c: circumcircle(all[a], all[b], all[c]) });
  let triangles = [make(corner, corner + 1, corner + 2)];
  for (const i of kept) {
    const [px, py] = all[i];
    const good = [];
    // The hole's boundary, in the order its edges are first met: edges of exactly one bad triangle.
    const edges = new Map();
    for (const t of triangles) {
      const dx = px - t.c.x, dy = py - t.c.y;
      if (!(dx * dx + dy * dy < t.c.r2 * (1 - 1e-12))) {
        good.push(t);
        continue;
      }
      for (let k = 0; k < 3; ++k) {
        const a = t.v[k], b = t.v[(k + 1) % 3], key = a < b ? a * 4294967296 + b : b * 4294967296 + a;
        edges.set(key, edges.has(key) ? null : [a, b]);
      }
    }
    triangles = good;
    for (const e of edges.values()) if (e) triangles.push(make(e[0], e[1], i));
  }
  return triangles.filter((t) => t.v.every((v) => v < corner)).map((t) => t.v);
}

// {points: [[p0, p1, p2], ...] (the cell's, then the border's), triangles: [[i, j, k], ...]}
export function buildWarpMesh(cell, width, height) {
  const points = cell.points.map((p) => p.map((v) => [v[0], v[1]]));
  for (const b of borderPoints(width, height)) points.push([b, b, b]);
  const pair = cell.samples.length === 2;
  const layout = points.map((p) =>
    pair ? [(p[0][0] + p[2][0]) / 2, (p[0][1] + p[2][1]) / 2] : [(p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3]);
  return { points, triangles: delaunayTriangles(layout) };
}
