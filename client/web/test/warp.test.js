// The browser's warps against the C++ client's (tests/golden/warp-vectors.json, written by
// WarpVectorsTest in tests/unit/warp_vectors_test.cpp): the same triangles, the same distance
// field, the same matte textures byte for byte, the same cell and weights for a view, the same
// photos fetched in the same order. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { finerToDrop, nextPhotoFetch, wantedLevel } from '../common/photo_fetch.js';
import { locateView, viewSamples } from '../common/view_sphere.js';
import { buildWarpMesh, delaunayTriangles } from '../common/warp_mesh.js';
import { distanceToSeeds, matteSample, objectOnMatte } from '../render/tween/matte_sample.js';

const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url)));
const bytes = (base64) => new Uint8ClampedArray(Buffer.from(base64, 'base64'));

test('Delaunay triangles are the C++ ones, in the same order, ties and near twins included', () => {
  for (const c of golden.delaunay) assert.deepEqual(delaunayTriangles(c.points), c.triangles, c.name);
});

test('a cell\'s warp mesh is the C++ one', () => {
  for (const c of golden.warp_meshes) {
    const mesh = buildWarpMesh({ samples: c.samples, points: c.points }, c.width, c.height);
    assert.equal(mesh.points.length, c.mesh_points);
    assert.deepEqual(mesh.triangles, c.triangles, `cell of ${c.samples.length}`);
  }
});

test('the distance field is the C++ one: distances and, on ties, the same nearest seed', () => {
  const { width, height, seed, distance, nearest } = golden.distance_field;
  const field = distanceToSeeds(Uint8Array.from(seed), width, height);
  assert.deepEqual(Array.from(field.distance), distance);
  assert.deepEqual(Array.from(field.nearest), nearest);
});

test('a photo and its matte make the C++ client\'s matte texture byte for byte, at a finer level too', () => {
  for (const c of golden.matte_samples) {
    const object = objectOnMatte(bytes(c.photo), bytes(c.matte), c.matte_width, c.matte_height, c.width, c.height);
    assert.deepEqual(object, bytes(c.object), `the object on its matte, ${c.width}x${c.height}`);
    assert.deepEqual(matteSample(object, c.width, c.height, c.scale), bytes(c.sample), `the matte texture, ${c.width}x${c.height}`);
  }
});

test('a view falls in the C++ client\'s cell with its weights', () => {
  const { directions, cells, views } = golden.locate_view;
  for (const v of views) {
    const at = locateView(directions, cells.map((samples) => ({ samples })), v.direction);
    assert.equal(at.cell, v.cell, `cell of ${v.direction}`);
    assert.equal(at.inside, v.inside);
    at.weights.forEach((w, k) => assert.ok(Math.abs(w - v.weights[k]) < 1e-5, `weight ${k}: ${w} against ${v.weights[k]}`));
    if (cells[v.cell].length === 2) assert.ok(Math.abs(at.t - v.t) < 1e-5, `t ${at.t} against ${v.t}`);
  }
});

test('photos are fetched in the C++ client\'s order as a visitor looks, turns and zooms', () => {
  const { directions, cells, first_height: firstHeight, level_heights: levelHeights, steps } = golden.photo_fetch;
  const hasFirst = new Set(), finer = new Map();
  for (const s of steps) {
    const wanted = wantedLevel(firstHeight, levelHeights, s.shown);
    assert.equal(wanted, s.wanted, `the level wanted ${s.shown} pixels high`);
    const fetched = [], dropped = [];
    for (let i = 0; i < s.fetches; ++i) {
      const next = nextPhotoFetch(directions, s.direction, viewSamples(directions, cells.map((samples) => ({ samples })), s.direction),
                                  (k) => hasFirst.has(k), (k) => finer.get(k) ?? 0, wanted);
      if (!next) break;
      fetched.push([next.sample, next.level]);
      if (next.level === 0) hasFirst.add(next.sample);
      else finer.set(next.sample, next.level);
      const drop = next.level > 0 ? finerToDrop(directions, next.sample, [...finer.keys()]) : -1;
      if (drop >= 0) finer.delete(drop), dropped.push(drop);
    }
    assert.deepEqual(fetched, s.fetched, `fetches from ${s.direction}`);
    assert.deepEqual(dropped, s.dropped, `finer levels given way at ${s.direction}`);
  }
});

test('the element compiles its shaders after the header the C++ renderer uses for WebGL2', async () => {
  const { kShaderHeader } = await import('../render/tween/tween_view.js');
  assert.equal(kShaderHeader, JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).shader_header);
});
