// The product manifest's reader (net/product_manifest.js, protocol/PRODUCT.md) fed a valid
// manifest, then thousands of mutations of it (keys removed, values of other types, numbers out
// of range, truncated text): each is read into a product within the limits or refused with the
// one-line reason the element shows, never anything else; and the manifest the C++ export wrote
// (tests/golden/product-manifest.json, by ProductManifestTest in
// tests/unit/product_manifest_test.cpp) read field for field. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { parseManifest } from '../net/product_manifest.js';

const hex = (i) => i.toString(16).padStart(64, '0');
const file = (i, ext) => ({ file: `files/${hex(i)}.${ext}`, sha256: hex(i), size: 1000 + i });
const n = 6;
const valid = {
  format: 'inkwire-product', version: 1, name: 'duck', width: 512, height: 384, distance_diagonals: 1.4, fov_y_degrees: 45,
  directions: Array.from({ length: n }, (_, i) => [Math.sin((i * Math.PI) / 3), 0, Math.cos((i * Math.PI) / 3)]),
  levels: [{ width: 1024, height: 768 }],
  photos: Array.from({ length: n }, (_, i) => file(i, 'jpg')),
  mattes: Array.from({ length: n }, (_, i) => file(100 + i, 'png')),
  zoom: [Array.from({ length: n }, (_, i) => file(200 + i, 'jpg'))],
  cells: Array.from({ length: n }, (_, i) => ({ pair: i, ...file(300 + i, 'cell') })),
};

test('a valid manifest reads as the product block and its files', () => {
  const m = parseManifest(JSON.stringify(valid));
  assert.equal(m.product.directions.length, n);
  assert.equal(m.product.cells, n);
  assert.deepEqual(m.product.levels, valid.levels);
  assert.equal(m.photos[2].file, valid.photos[2].file);
  assert.equal(m.zoom[0].length, n);
});

test('the manifest the C++ export wrote reads field for field, and holds no field the reader skips', () => {
  const text = readFileSync(new URL('../../../tests/golden/product-manifest.json', import.meta.url), 'utf8');
  const written = JSON.parse(text);
  const m = parseManifest(text);
  assert.deepEqual(Object.keys(written).sort(),
                   ['cells', 'directions', 'distance_diagonals', 'format', 'fov_y_degrees', 'height', 'levels', 'mattes', 'name', 'photos', 'version', 'width', 'zoom'],
                   'a field the C++ writes that this reader does not read (or one it no longer writes)');
  assert.equal(written.format, 'inkwire-product');
  assert.equal(written.version, 1);
  assert.equal(m.name, written.name);
  assert.deepEqual(m.product, {
    width: written.width, height: written.height, directions: written.directions, cells: written.cells.length, levels: written.levels,
    distance_diagonals: written.distance_diagonals, fov_y_degrees: written.fov_y_degrees,
  });
  assert.deepEqual(m.photos, written.photos);
  assert.deepEqual(m.mattes, written.mattes);
  assert.deepEqual(m.zoom, written.zoom);
  assert.deepEqual(m.cells, written.cells);
  // What the test product is: four matted views 32 x 24, one zoom level at twice the size, a cell a pair.
  assert.equal(m.name, 'disc');
  assert.deepEqual([m.product.width, m.product.height, m.product.directions.length, m.product.cells], [32, 24, 4, 4]);
  assert.deepEqual(m.product.levels, [{ width: 64, height: 48 }]);
  assert.ok(Math.abs(m.product.distance_diagonals - 1.6) < 1e-6 && m.product.fov_y_degrees === 40);
  assert.deepEqual([m.photos.length, m.mattes.length, m.zoom.length, m.zoom[0].length], [4, 4, 1, 4]);
  assert.ok(m.photos.every((f) => f.file.endsWith('.jpg')) && m.mattes.every((f) => f.file.endsWith('.png')));
  assert.ok(m.zoom[0].every((f) => f.file.endsWith('.jpg')) && m.cells.every((c) => c.file.endsWith('.cell')));
});

test('another version, a file not named by its hash, a missing photo each give their reason', () => {
  assert.throws(() => parseManifest(JSON.stringify({ ...valid, version: 2 })), /version 2, this element reads version 1/);
  assert.throws(() => parseManifest(JSON.stringify({ ...valid, photos: [{ ...file(0, 'jpg'), file: '../../etc/passwd' }, ...valid.photos.slice(1)] })),
                /not files\/ named by its hash/);
  assert.throws(() => parseManifest(JSON.stringify({ ...valid, photos: valid.photos.slice(1) })), /5 photos for 6 directions/);
});

// A small deterministic generator, so a failure is the same on every run.
function random(seed) {
  let s = seed >>> 0;
  return () => ((s = (s * 1664525 + 1013904223) >>> 0) / 2 ** 32);
}

function mutate(value, r) {
  if (Array.isArray(value) || (typeof value === 'object' && value !== null)) {
    const copy = Array.isArray(value) ? [...value] : { ...value };
    const keys = Object.keys(copy);
    if (!keys.length) return copy;
    const key = keys[Math.floor(r() * keys.length)];
    const roll = r();
    if (roll < 0.15) delete copy[key];
    else if (roll < 0.8) copy[key] = mutate(copy[key], r);
    else copy[key] = [null, -1, 0, 1e9, 'x', [], {}, true, NaN, 3.5, '../x'][Math.floor(r() * 11)];
    return copy;
  }
  const odd = [null, -1, 0, 1e9, 'x', [], {}, true, 3.5, -0.5, '0'.repeat(64), `files/${'0'.repeat(64)}.exe`];
  return r() < 0.5 ? odd[Math.floor(r() * odd.length)] : typeof value === 'number' ? value * (r() * 4 - 2) : value;
}

test('five thousand mutated manifests are read within the limits or refused with a reason', () => {
  const r = random(1234);
  let read = 0;
  for (let i = 0; i < 5000; ++i) {
    let text = JSON.stringify(mutate(mutate(valid, r), r));
    if (r() < 0.1) text = text.slice(0, Math.floor(r() * text.length));
    try {
      const m = parseManifest(text);
      ++read;
      assert.ok(m.product.width >= 1 && m.product.width <= 4096 && m.product.directions.length >= 2);
      assert.equal(m.photos.length, m.product.directions.length);
      assert.ok(m.cells.every((c, k) => c.pair === k && /^files\/[0-9a-f]{64}\.cell$/.test(c.file)));
      assert.ok([...m.photos, ...m.mattes, ...m.zoom.flat()].every((f) => f.file.includes(f.sha256) && f.size >= 1));
    } catch (error) {
      if (error instanceof assert.AssertionError) throw error;
      assert.ok(error instanceof Error && error.message.startsWith("the product's manifest: "), `${error.message} for ${text.slice(0, 200)}`);
    }
  }
  assert.ok(read > 50, `only ${read} mutated manifests were valid: the mutations say little`);
});
