// The turntable's framing (common/framing.js) against the C++ client's (common/camera.hpp
// fit_scale), case by case (tests/golden/warp-vectors.json "framing", written by
// WarpVectorsTest). Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { fitScale } from '../common/framing.js';

const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).framing;

test('photos fit an element of any shape as the native client fits them', () => {
  assert.ok(golden.length > 0);
  for (const c of golden) {
    const scale = fitScale(c.viewport_aspect, c.picture_aspect);
    assert.ok(Math.abs(scale - c.scale) <= 1e-6, `${JSON.stringify(c)}: ${scale}`);
  }
});
