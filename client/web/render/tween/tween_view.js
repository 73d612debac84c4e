// A product drawn in WebGL2 (SPEC W2), mirroring client/render/tween/tween_renderer.cpp and
// client/viewer/turntable_view.cpp: sample photos warped along the product's tween data into
// the view, composed by their mattes in one pass (image_warper.cpp's one-pass view), bilinear
// on a ring, trilinear on a sphere. Until a view's cell and its photos are there, the nearest
// photo that is shows, as it is.
import { fitScale } from '../../common/framing.js';
import { finerToDrop } from '../../common/photo_fetch.js';
import { pathWeights } from '../../common/tween_data.js';
import { locateView, nearestSample, viewSamples } from '../../common/view_sphere.js';
import { buildWarpMesh } from '../../common/warp_mesh.js';
import { kBleedPixels, kMatteRange } from './matte_sample.js';

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`TweenView: shader: ${gl.getShaderInfoLog(shader)}`);
  return shader;
}

// What client/gl/resources.cpp shader_header() puts before every shader in the WebAssembly
// build (kWebGlShaderHeader; warp-vectors.json "shader_header" pins the two): the shader files
// carry no #version, so the C++ client's files serve the browser too.
export const kShaderHeader = '#version 300 es\nprecision highp float;\nprecision highp int;\n' +
  'precision highp sampler2D;\nprecision highp sampler2DArray;\nprecision highp sampler3D;\n';

export function program(gl, vertex, fragment, defines) {
  const withHeader = (src) => `${kShaderHeader}${defines.map((d) => `#define ${d}\n`).join('')}${src}`;
  const p = gl.createProgram();
  gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, withHeader(vertex)));
  gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, withHeader(fragment)));
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(`TweenView: link: ${gl.getProgramInfoLog(p)}`);
  return p;
}

// The C++ client's own tween shaders (client/shaders/tween/), which the server serves as they are.
export async function loadTweenShaders() {
  const get = async (name) => (await fetch(new URL(`../../shaders/tween/${name}`, import.meta.url))).text();
  return { vertex: await get('blend.vert'), fragment: await get('blend.frag') };
}


export class TweenView {
  // `product`: a snapshot's product block; `shaders`: from loadTweenShaders().
  constructor(gl, product, shaders) {
    this.gl = gl;
    this.product = product;
    this.programs = [1, 2, 3].map((n) => program(gl, shaders.vertex, shaders.fragment, [`SAMPLES ${n}`, 'MATTE', `MATTE_RANGE ${kMatteRange.toFixed(1)}`, `BLEED ${kBleedPixels.toFixed(1)}`]));
    this.textures = new Array(product.directions.length).fill(null);
    // Zoom (SPEC T18): samples holding a finer level, index -> {texture, level}; drawn from while
    // useFiner is on; at most kFinerKept of them (photo_fetch.js finerToDrop()).
    this.finer = new Map();
    this.useFiner = false;
    this.finerInView = 0;
    this.cells = new Array(product.cells).fill(null);
    this.meshes = new Array(product.cells).fill(null);
    this.plain = this.upload(buildWarpMesh({ samples: [0, 1], points: [] }, product.width, product.height));
    this.lastCell = -1;
  }

  get samplesLoaded() { return this.textures.filter(Boolean).length; }
  get cellsLoaded() { return this.cells.filter(Boolean).length; }

  upload(mesh) {
    const gl = this.gl;
    const vertices = new Float32Array(mesh.points.flatMap((p) => [p[0][0], p[0][1], p[1][0], p[1][1], p[2][0], p[2][1]]));
    const indices = new Uint32Array(mesh.triangles.flat());
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, vertices, gl.STATIC_DRAW);
    for (let k = 0; k < 3; ++k) {
      gl.enableVertexAttribArray(k);
      gl.vertexAttribPointer(k, 2, gl.FLOAT, false, 24, 8 * k);
    }
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return { vao, count: indices.length };
  }

  // `rgba`: the sample's matte texture bytes (matteSample()).
  setSample(index, rgba) {
    this.textures[index] = this.texture(rgba, this.product.width, this.product.height);
  }

  // Sample `index` at zoom level `level` (1: the product's levels[0]), `rgba` of its size.
  setFiner(index, level, rgba) {
    const { width, height } = this.product.levels[level - 1];
    const before = this.finer.get(index);
    if (before) this.gl.deleteTexture(before.texture);
    this.finer.set(index, { texture: this.texture(rgba, width, height), level });
    const drop = finerToDrop(this.product.directions, index, [...this.finer.keys()]);
    if (drop < 0) return;
    this.gl.deleteTexture(this.finer.get(drop).texture);
    this.finer.delete(drop);
  }

  finerLevel(index) { return this.finer.get(index)?.level ?? 0; }

  // Sample `index` as the view reads it: its finer level while finer views are asked for.
  textureOf(index) { return (this.useFiner && this.finer.get(index)?.texture) || this.textures[index]; }

  // The samples a view from `direction` is drawn from once they are there (view_sphere.js).
  viewSamples(direction) { return viewSamples(this.product.directions, this.cells, direction); }

  texture(rgba, width, height) {
    const gl = this.gl;
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, width, height, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(rgba.buffer, rgba.byteOffset, rgba.byteLength));
    for (const [k, v] of [[gl.TEXTURE_MIN_FILTER, gl.LINEAR], [gl.TEXTURE_MAG_FILTER, gl.LINEAR], [gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE],
                          [gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE]])
      gl.texParameteri(gl.TEXTURE_2D, k, v);
    return texture;
  }

  addCell(index, cell) {
    if (index < 0 || index >= this.cells.length || this.cells[index]) return;
    this.cells[index] = cell;
    this.meshes[index] = this.upload(buildWarpMesh(cell, this.product.width, this.product.height));
  }

  // The nearest photo that is there, drawn as it is.
  nearestLoaded(direction) {
    const best = nearestSample(this.product.directions, direction, (i) => this.textures[i]);
    return best < 0 ? null : { mesh: this.plain, positions: [1, 0, 0], sources: [{ sample: best, slot: 0, weight: 1 }], sample: best };
  }

  plan(direction) {
    const at = locateView(this.product.directions, this.cells, direction);
    this.lastCell = at.cell;
    const fallback = this.nearestLoaded(direction);
    if (at.cell < 0) return fallback;
    const cell = this.cells[at.cell], pair = cell.samples.length === 2;
    // Until every sample of the cell is there, outside every cell, or in a pair that does not
    // hold the nearest sample, the nearest that is (as tween_renderer.cpp says why).
    const whole = cell.samples.every((s) => this.textures[s]);
    const holdsNearest = fallback && cell.samples.includes(fallback.sample);
    if (!whole || !at.inside || (pair && !holdsNearest)) {
      this.lastCell = -1;
      return fallback;
    }
    return {
      mesh: this.meshes[at.cell],
      positions: pair ? pathWeights(at.t) : at.weights,
      sources: cell.samples.map((s, k) => ({ sample: s, slot: pair ? 2 * k : k, weight: at.weights[k] })),
    };
  }

  // A program's uniform locations, looked up once.
  locations(p) {
    if (!p.locations) {
      p.locations = {};
      for (const name of ['samples[0]', 'samples[1]', 'samples[2]', 'sample_size[0]', 'sample_size[1]', 'sample_size[2]', 'position_weights',
                          'source', 'weights', 'to_clip', 'depth'])
        p.locations[name] = this.gl.getUniformLocation(p, name);
    }
    return p.locations;
  }

  // Draws the view from `direction` (unit, from the object toward the eye) into the bound
  // framebuffer of `viewport` [w, h] pixels, `zoom` times the photos' own scale, over what is there.
  draw(viewport, direction, zoom = 1) {
    const gl = this.gl, view = this.plan(direction);
    if (!view) return false;
    const { width, height } = this.product;
    // Letterboxed: a viewport narrower than the photos shows them whole.
    const h = viewport[1] * zoom * fitScale(viewport[0] / viewport[1], width / height), w = (h * width) / height;
    const rect = [(viewport[0] - w) / 2, (viewport[1] - h) / 2, w, h];
    // Image pixel (y down) -> window pixel in rect (y up) -> clip space.
    const toClip = [(2 * rect[2]) / (width * viewport[0]), (-2 * rect[3]) / (height * viewport[1]), (2 * rect[0]) / viewport[0] - 1,
                    (2 * (rect[1] + rect[3])) / viewport[1] - 1];
    this.finerInView = this.useFiner ? view.sources.filter((s) => this.finer.has(s.sample)).length : 0;
    const p = this.programs[view.sources.length - 1];
    const at = this.locations(p);
    gl.useProgram(p);
    const source = [0, 0, 0], weights = [0, 0, 0];
    view.sources.forEach((s, k) => {
      source[k] = s.slot;
      weights[k] = s.weight;
      gl.activeTexture(gl.TEXTURE0 + k);
      gl.bindTexture(gl.TEXTURE_2D, this.textureOf(s.sample));
      gl.uniform1i(at[`samples[${k}]`], k);
      gl.uniform2f(at[`sample_size[${k}]`], width, height);  // control points are in first-level pixels, whatever the level
    });
    gl.uniform3fv(at.position_weights, view.positions);
    gl.uniform3iv(at.source, source);
    gl.uniform3fv(at.weights, weights);
    gl.uniform4fv(at.to_clip, toClip);
    gl.uniform1f(at.depth, 0.5);
    // Folded triangles are written once: depth-tested at one depth against a cleared buffer.
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.disable(gl.CULL_FACE);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.bindVertexArray(view.mesh.vao);
    gl.drawElements(gl.TRIANGLES, view.mesh.count, gl.UNSIGNED_INT, 0);
    gl.bindVertexArray(null);
    gl.disable(gl.BLEND);
    return true;
  }
}
