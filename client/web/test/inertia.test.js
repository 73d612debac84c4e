// The element's inertia (common/inertia.js) against the native window's (client/viewer/
// window_input.hpp), step by step (tests/golden/warp-vectors.json "inertia", written by
// WarpVectorsTest). Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { coast, draggedVelocity, kDegreesPerPixel, kInertiaSeconds, kInertiaStop, kMaxTurnSpeed } from '../common/inertia.js';

const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).inertia;
// C++ reckons in float, the script in double.
const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 1e-3 * Math.max(1, Math.abs(b)), `${what}: ${a} against ${b}`);

test('a drag leaves the speed the native window keeps, at most a turn a second', () => {
  [kMaxTurnSpeed, kInertiaSeconds, kInertiaStop].forEach((value, i) => near(value, golden.limits[i], 'the rule\'s constants'));
  near(kDegreesPerPixel, golden.degrees_per_pixel, 'a drag\'s degrees a pixel');
  for (const step of golden.drags) near(draggedVelocity(step.velocity, step.degrees, step.seconds), step.next, JSON.stringify(step));
});

test('a let-go turn coasts and stops as the native window does', () => {
  for (const step of golden.coasts) {
    const { turn, velocity } = coast(step.velocity, step.seconds);
    near(turn, step.turn, `turn ${JSON.stringify(step)}`);
    near(velocity, step.next, `speed ${JSON.stringify(step)}`);
  }
});
