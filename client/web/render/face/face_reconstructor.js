// Face reconstruction in WebGL2 (SPEC W3, F5), mirroring client/render/face/face_reconstructor.cpp:
// the neutral photo warped over a triangulation of its 68 landmarks, a fixed ring of anchors
// around the face and the image border; the landmarks moved by the received expression's
// template, tweened over 100 ms; an opening mouth of a closed-mouthed photo shows a dark cavity.
import { applyExpression } from '../../common/face.js';
import { buildFaceMesh, cavityColour, kCavityRows } from '../../common/face_mesh.js';
import { program } from '../tween/tween_view.js';

export class FaceReconstructor {
  // `photo`: RGBA bytes; `landmarks`: 68 [x, y]; `templates`: parseTemplates().
  constructor(gl, photo, width, height, landmarks, templates, shaders, tweenSeconds = 0.1) {
    if (width < 16 || height < 16) throw new Error('face reconstruction: the neutral photo is too small');
    for (const [x, y] of landmarks) if (!(x >= 0 && y >= 0 && x <= width && y <= height)) throw new Error('face reconstruction: a landmark lies outside the photo');
    Object.assign(this, { gl, width, height, neutral: landmarks, templates, tweenSeconds });
    ({ points: this.points, triangles: this.triangles, landmarkOf: this.landmarkOf } = buildFaceMesh(landmarks, templates, width, height));
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
