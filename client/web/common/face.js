// The 68-point face layout and its normalised frame, expression templates and their
// application, mirroring common/face/face_shape.cpp, common/face/expression.cpp and
// common/face/expression_templates.cpp: origin between the eye centres, x along the eye line,
// y down, one unit = the inter-ocular distance.
export const kFaceLandmarks = 68;
export const kExpressionNames = ['neutral', 'smile', 'laugh', 'frown', 'surprise', 'sad', 'eyes-closed', 'wink-left', 'wink-right',
                                 'viseme-closed', 'viseme-open', 'viseme-wide', 'viseme-round'];
const kMaxOffset = 2;

const eyeCentre = (p, first) => [(p[first][0] + p[first + 3][0]) / 2, (p[first][1] + p[first + 3][1]) / 2];

// {origin, axis, scale} of a face; throws when the eyes coincide (not a face).
export function faceFrame(landmarks) {
  const left = eyeCentre(landmarks, 36), right = eyeCentre(landmarks, 42);
  const distance = Math.hypot(right[0] - left[0], right[1] - left[1]);
  if (!(distance > 1e-3)) throw new Error('face landmarks: the eyes coincide');
  return { origin: [(left[0] + right[0]) / 2, (left[1] + right[1]) / 2], axis: [(right[0] - left[0]) / distance, (right[1] - left[1]) / distance], scale: distance };
}
export function offsetToImage(frame, [x, y]) {
  const [ax, ay] = frame.axis;  // perpendicular: (-ay, ax), x turned a quarter towards y (down)
  return [frame.scale * (x * ax - y * ay), frame.scale * (x * ay + y * ax)];
}
export function toImage(frame, p) {
  const o = offsetToImage(frame, p);
  return [frame.origin[0] + o[0], frame.origin[1] + o[1]];
}
export function toFace(frame, [x, y]) {
  const dx = (x - frame.origin[0]) / frame.scale, dy = (y - frame.origin[1]) / frame.scale, [ax, ay] = frame.axis;
  return [dx * ax + dy * ay, -dx * ay + dy * ax];
}

// The shipped templates file, checked as the C++ reader checks it: {name: offsets[68]}.
export function parseTemplates(json) {
  if (json.format !== 'inkwire-expression-templates' || json.version !== 1) throw new Error('expression templates: not version 1 of the format');
  const templates = { neutral: null };
  for (const [name, entry] of Object.entries(json.templates ?? {})) {
    if (!kExpressionNames.includes(name)) throw new Error(`expression templates: unknown expression '${name}'`);
    const offsets = entry.offsets;
    if (!Array.isArray(offsets) || offsets.length !== kFaceLandmarks) throw new Error(`expression templates: '${name}' needs 68 offsets`);
    for (const p of offsets)
      if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => Number.isFinite(v) && Math.abs(v) <= kMaxOffset))
        throw new Error(`expression templates: '${name}' has an offset that is not finite or too large`);
    templates[name] = offsets;
  }
  return templates;
}

// A landmarks asset (protocol/SPEC.md "Conference sessions"): 68 finite points.
export function parseLandmarks(json) {
  if (json.format !== 'inkwire-face-landmarks' || !Array.isArray(json.points) || json.points.length !== kFaceLandmarks)
    throw new Error('face landmarks: not 68 points of the inkwire-face-landmarks format');
  for (const p of json.points)
    if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => Number.isFinite(v) && Math.abs(v) <= 1e6)) throw new Error('face landmarks: a point is not finite');
  return json.points.map((p) => [p[0], p[1]]);
}

// The landmarks of `neutral` moved by an expression's template at `intensity` (0-255).
export function applyExpression(neutral, templates, code, intensity) {
  const offsets = templates[kExpressionNames[code]];
  if (!offsets) return neutral.map((p) => [p[0], p[1]]);
  const frame = faceFrame(neutral), amount = intensity / 255;
  return neutral.map((p, i) => {
    const o = offsetToImage(frame, [amount * offsets[i][0], amount * offsets[i][1]]);
    return [p[0] + o[0], p[1] + o[1]];
  });
}
