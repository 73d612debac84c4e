// The mesh a face is redrawn over (SPEC F5), as the C++ builds it (common/face/face_mesh.cpp),
// pinned by tests/golden/warp-vectors.json: the neutral photo's 68 landmarks, a fixed ring of
// anchors around the face and the image border, triangulated with the mouth open; when the
// photo's mouth is closed, the triangles inside the inner lips read a strip of dark mouth-cavity
// colour under the photo (the atlas) instead of stretched lips.
import { applyExpression, faceFrame, kFaceLandmarks, toFace, toImage } from './face.js';
import { borderPoints, delaunayTriangles } from './warp_mesh.js';

export const kCavityRows = 8;    // the atlas strip under the photo that cavity triangles read
const kClosedMouthGap = 0.04;    // inner lips closer than this (inter-ocular) count as closed
const kVisemeOpen = 10;

// Anchors around the face (face frame): the jaw line pushed out from the face centre and the
// brows lifted to the hairline; they stay where they are.
function faceAnchors(face) {
  const centre = [0, 0.45], anchors = [];
  for (let i = 0; i <= 16; i += 2) anchors.push([centre[0] + 1.6 * (face[i][0] - centre[0]), centre[1] + 1.6 * (face[i][1] - centre[1])]);
  for (let i = 17; i <= 26; i += 3) anchors.push([face[i][0], face[i][1] - 0.8]);
  anchors.push([face[26][0], face[26][1] - 0.8]);
  return anchors;
}

function inside(polygon, [x, y]) {  // even-odd rule
  let result = false;
  for (let i = 0, j = polygon.length - 1; i < polygon.length; j = i++) {
    const [ax, ay] = polygon[i], [bx, by] = polygon[j];
    if ((ay > y) !== (by > y) && x < ((bx - ax) * (y - ay)) / (by - ay) + ax) result = !result;
  }
  return result;
}

// {points: per point [atlas position, drawn position, unused], triangles, landmarkOf: per point
// the landmark it follows or -1} for a `width` x `height` photo whose face has `landmarks`.
export function buildFaceMesh(landmarks, templates, width, height) {
  const frame = faceFrame(landmarks), face = landmarks.map((p) => toFace(frame, p));
  const points = landmarks.map((p) => [p[0], p[1]]);
  const landmarkOf = points.map((_, i) => i);
  // Anchors near or past the image edge are left out (the border points hold the frame there).
  const margin = 0.04 * Math.min(width, height);
  for (const f of faceAnchors(face)) {
    const a = toImage(frame, f);
    if (a[0] > margin && a[1] > margin && a[0] < width - margin && a[1] < height - margin) points.push(a);
  }
  for (const b of borderPoints(width, height)) points.push(b);
  while (landmarkOf.length < points.length) landmarkOf.push(-1);
  // Triangulated with the mouth open, so the inner lips are apart.
  const open = applyExpression(landmarks, templates, kVisemeOpen, 255);
  const layout = points.map((p, i) => (i < kFaceLandmarks ? open[i] : p));
  const innerLips = open.slice(60, 68);
  const d = (a, b) => Math.hypot(face[a][0] - face[b][0], face[a][1] - face[b][1]);
  const fillCavity = (d(61, 67) + d(62, 66) + d(63, 65)) / 3 < kClosedMouthGap;
  const mesh = { points: points.map((p) => [p, p, p]), triangles: [], landmarkOf };
  const cavityY = height + 0.5 * kCavityRows;
  for (const t of delaunayTriangles(layout)) {
    const centroid = [0, 1].map((k) => (layout[t[0]][k] + layout[t[1]][k] + layout[t[2]][k]) / 3);
    const mouth = t.every((v) => v >= 60 && v < 68);
    if (!(fillCavity && mouth && inside(innerLips, centroid))) {
      mesh.triangles.push(t);
      continue;
    }
    // Cavity: its own copies of the corners, reading the dark strip under the photo.
    mesh.triangles.push(t.map((v) => {
      mesh.points.push([[points[v][0], cavityY], points[v], points[v]]);
      landmarkOf.push(v);
      return mesh.points.length - 1;
    }));
  }
  return mesh;
}

// The mouth cavity's colour [r, g, b]: the photo's lip colour darkened.
export function cavityColour(photo, width, height, p) {
  const sum = [0, 0, 0];
  for (let i = 48; i <= 59; ++i) {
    const j = 60 + Math.trunc(((i - 48) * 8) / 12);
    const x = Math.min(Math.max(Math.trunc(0.5 * (p[i][0] + p[j][0])), 0), width - 1);
    const y = Math.min(Math.max(Math.trunc(0.5 * (p[i][1] + p[j][1])), 0), height - 1);
    for (let c = 0; c < 3; ++c) sum[c] += photo[4 * (y * width + x) + c];
  }
  return sum.map((v) => Math.trunc((0.3 * v) / 12));
}
