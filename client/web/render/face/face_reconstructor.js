// Face reconstruction in WebGL2 (SPEC W3, F5), mirroring client/render/face/face_reconstructor.cpp:
// the neutral photo warped over a triangulation of its 68 landmarks, a fixed ring of anchors
// around the face and the image border; the landmarks moved by the received expression's
// template, tweened over 100 ms; an opening mouth of a closed-mouthed photo shows a dark cavity.
import { applyExpression, faceFrame, kFaceLandmarks, toFace, toImage } from '../../common/face.js';
import { borderPoints, delaunayTriangles } from '../../common/warp_mesh.js';
import { program } from '../tween/tween_view.js';

const kCavityRows = 8;           // the atlas strip under the photo that cavity triangles read
const kClosedMouthGap = 0.04;    // inner lips closer than this (inter-ocular) count as closed
const kVisemeOpen = 10;

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

function cavityColour(photo, width, height, p) {
  const sum = [0, 0, 0];
  for (let i = 48; i <= 59; ++i) {
    const j = 60 + Math.trunc(((i - 48) * 8) / 12);
    const x = Math.min(Math.max(Math.trunc(0.5 * (p[i][0] + p[j][0])), 0), width - 1);
    const y = Math.min(Math.max(Math.trunc(0.5 * (p[i][1] + p[j][1])), 0), height - 1);
    for (let c = 0; c < 3; ++c) sum[c] += photo[4 * (y * width + x) + c];
  }
  return sum.map((v) => Math.trunc((0.3 * v) / 12));
}

export class FaceReconstructor {
  // `photo`: RGBA bytes; `landmarks`: 68 [x, y]; `templates`: parseTemplates().
  constructor(gl, photo, width, height, landmarks, templates, shaders, tweenSeconds = 0.1) {
    if (width < 16 || height < 16) throw new Error('face reconstruction: the neutral photo is too small');
    for (const [x, y] of landmarks) if (!(x >= 0 && y >= 0 && x <= width && y <= height)) throw new Error('face reconstruction: a landmark lies outside the photo');
    Object.assign(this, { gl, width, height, neutral: landmarks, templates, tweenSeconds });
    const frame = faceFrame(landmarks), face = landmarks.map((p) => toFace(frame, p));
    const points = landmarks.map((p) => [p[0], p[1]]);
    this.landmarkOf = points.map((_, i) => i);
    const margin = 0.04 * Math.min(width, height);
    for (const f of faceAnchors(face)) {
      const a = toImage(frame, f);
      if (a[0] > margin && a[1] > margin && a[0] < width - margin && a[1] < height - margin) points.push(a);
    }
    for (const b of borderPoints(width, height)) points.push(b);
    while (this.landmarkOf.length < points.length) this.landmarkOf.push(-1);
    // Triangulated with the mouth open, so the inner lips are apart.
    const open = applyExpression(landmarks, templates, kVisemeOpen, 255);
    const layout = points.map((p, i) => (i < kFaceLandmarks ? open[i] : p));
    const triangles = delaunayTriangles(layout);
    const innerLips = open.slice(60, 68);
    const d = (a, b) => Math.hypot(face[a][0] - face[b][0], face[a][1] - face[b][1]);
    const fillCavity = (d(61, 67) + d(62, 66) + d(63, 65)) / 3 < kClosedMouthGap;
    this.points = points.map((p) => [p, p, p]);
    this.triangles = [];
    const cavityY = height + 0.5 * kCavityRows;
    for (const t of triangles) {
      const centroid = [0, 1].map((k) => (layout[t[0]][k] + layout[t[1]][k] + layout[t[2]][k]) / 3);
      const mouth = t.every((v) => v >= 60 && v < 68);
      if (!(fillCavity && mouth && inside(innerLips, centroid))) {
        this.triangles.push(t);
        continue;
      }
      const copy = t.map((v) => {
        this.points.push([[points[v][0], cavityY], points[v], points[v]]);
        this.landmarkOf.push(v);
        return this.points.length - 1;
      });
      this.triangles.push(copy);
    }
    // The atlas: the photo, and under it a strip of the mouth cavity's colour.
    const atlas = new Uint8Array(width * (height + kCavityRows) * 4);
    atlas.set(photo);
    const cavity = cavityColour(photo, width, height, landmarks);
    for (let i = photo.length; i < atlas.length; i += 4) atlas.set([...cavity, 255], i);
    this.texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, width, height + kCavityRows, 0, gl.RGBA, gl.UNSIGNED_BYTE, atlas);
    for (const [k, v] of [[gl.TEXTURE_MIN_FILTER, gl.LINEAR], [gl.TEXTURE_MAG_FILTER, gl.LINEAR], [gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE],
                          [gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE]])
      gl.texParameteri(gl.TEXTURE_2D, k, v);
    this.program = program(gl, shaders.vertex, shaders.fragment, ['SAMPLES 1']);
    this.vao = gl.createVertexArray();
    gl.bindVertexArray(this.vao);
    this.vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, this.vbo);
    gl.bufferData(gl.ARRAY_BUFFER, this.points.length * 24, gl.DYNAMIC_DRAW);
    for (let k = 0; k < 3; ++k) {
      gl.enableVertexAttribArray(k);
      gl.vertexAttribPointer(k, 2, gl.FLOAT, false, 24, 8 * k);
    }
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(this.triangles.flat()), gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    this.from = landmarks;
    this.to = landmarks;
    this.start = 0;
    this.code = 0;
    this.intensity = 0;
  }

  // From what is shown at `now` (seconds), tween to the expression over tweenSeconds.
  setExpression(code, intensity, now) {
    this.from = this.landmarksAt(now);
    this.to = applyExpression(this.neutral, this.templates, code, intensity);
    this.start = now;
    this.code = code;
    this.intensity = intensity;
  }

  landmarksAt(now) {
    const t = this.tweenSeconds > 0 ? Math.min(Math.max((now - this.start) / this.tweenSeconds, 0), 1) : 1;
    const s = t * t * (3 - 2 * t);  // ease in and out
    return this.from.map((p, i) => [p[0] + (this.to[i][0] - p[0]) * s, p[1] + (this.to[i][1] - p[1]) * s]);
  }

  settled(now) { return now - this.start >= this.tweenSeconds; }

  // Draws the face shown at `now` into `rect` [x, y, w, h] (window pixels, y up) of `viewport`.
  draw(now, viewport, rect) {
    const gl = this.gl, shown = this.landmarksAt(now);
    const data = new Float32Array(this.points.length * 6);
    this.points.forEach((p, i) => {
      const target = this.landmarkOf[i] >= 0 ? shown[this.landmarkOf[i]] : p[1];
      data.set([p[0][0], p[0][1], target[0], target[1], p[2][0], p[2][1]], 6 * i);
    });
    gl.bindBuffer(gl.ARRAY_BUFFER, this.vbo);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, data);
    const { width, height } = this;
    const toClip = [(2 * rect[2]) / (width * viewport[0]), (-2 * rect[3]) / (height * viewport[1]), (2 * rect[0]) / viewport[0] - 1,
                    (2 * (rect[1] + rect[3])) / viewport[1] - 1];
    const p = this.program;
    gl.useProgram(p);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.texture);
    gl.uniform1i(gl.getUniformLocation(p, 'samples[0]'), 0);
    gl.uniform3fv(gl.getUniformLocation(p, 'position_weights'), [0, 1, 0]);
    gl.uniform3iv(gl.getUniformLocation(p, 'source'), [0, 0, 0]);
    gl.uniform3fv(gl.getUniformLocation(p, 'weights'), [1, 0, 0]);
    gl.uniform2f(gl.getUniformLocation(p, 'sample_size[0]'), width, height + kCavityRows);
    gl.uniform1f(gl.getUniformLocation(p, 'depth'), 0.5);
    gl.uniform4fv(gl.getUniformLocation(p, 'to_clip'), toClip);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.bindVertexArray(this.vao);
    gl.drawElements(gl.TRIANGLES, this.triangles.length * 3, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
    gl.disable(gl.BLEND);
  }
}
