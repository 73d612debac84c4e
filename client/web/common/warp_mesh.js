// The triangulated control points a warp draws, mirroring common/tween/warp_mesh.cpp: the
// cell's points plus fixed points along the image border, Delaunay triangles on the pairs'
// halfway positions (triangles' centroids), points within 1/8 pixel of an earlier one left out.

// Border points every quarter side, corners included, the same in every sample.
export function borderPoints(width, height, perSide = 4) {
  const out = [];
  for (let i = 0; i < perSide; ++i) {
    const f = i / perSide;
    out.push([f * width, 0], [width, f * height], [(1 - f) * width, height], [0, (1 - f) * height]);
  }
  return out;
}

// Delaunay triangles of `points` ([x, y] each) as index triples (Bowyer-Watson).
export function delaunayTriangles(points) {
  if (points.length < 3) return [];
  const kept = [];
  for (let i = 0; i < points.length; ++i) {
    const p = points[i];
    if (kept.some((j) => Math.hypot(points[j][0] - p[0], points[j][1] - p[1]) < 0.125)) continue;
    kept.push(i);
  }
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const i of kept) {
    minX = Math.min(minX, points[i][0]), maxX = Math.max(maxX, points[i][0]);
    minY = Math.min(minY, points[i][1]), maxY = Math.max(maxY, points[i][1]);
  }
  const span = Math.max(maxX - minX, maxY - minY, 1) * 20, cx = (minX + maxX) / 2, cy = (minY + maxY) / 2;
  const all = points.map((p) => [p[0], p[1]]);
  const s0 = all.push([cx - span, cy - span]) - 1, s1 = all.push([cx + span, cy - span]) - 1, s2 = all.push([cx, cy + span]) - 1;
  const circumcircle = (a, b, c) => {
    const [ax, ay] = all[a], [bx, by] = all[b], [cx2, cy2] = all[c];
    const d = 2 * (ax * (by - cy2) + bx * (cy2 - ay) + cx2 * (ay - by));
    const ux = ((ax * ax + ay * ay) * (by - cy2) + (bx * bx + by * by) * (cy2 - ay) + (cx2 * cx2 + cy2 * cy2) * (ay - by)) / d;
    const uy = ((ax * ax + ay * ay) * (cx2 - bx) + (bx * bx + by * by) * (ax - cx2) + (cx2 * cx2 + cy2 * cy2) * (bx - ax)) / d;
    return { x: ux, y: uy, r2: (ax - ux) ** 2 + (ay - uy) ** 2 };
  };
  let triangles = [{ v: [s0, s1, s2], c: circumcircle(s0, s1, s2) }];
  for (const i of kept) {
    const [px, py] = all[i];
    const bad = [], good = [];
    for (const t of triangles) ((px - t.c.x) ** 2 + (py - t.c.y) ** 2 < t.c.r2 * (1 - 1e-12) ? bad : good).push(t);
    // The hole's boundary: edges of exactly one bad triangle.
    const edges = new Map();
    for (const t of bad)
      for (let k = 0; k < 3; ++k) {
        const a = t.v[k], b = t.v[(k + 1) % 3], key = a < b ? `${a},${b}` : `${b},${a}`;
        edges.set(key, edges.has(key) ? null : [a, b]);
      }
    triangles = good;
    for (const e of edges.values()) if (e) triangles.push({ v: [e[0], e[1], i], c: circumcircle(e[0], e[1], i) });
  }
  return triangles.filter((t) => t.v.every((v) => v < points.length)).map((t) => t.v);
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
