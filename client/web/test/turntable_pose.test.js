// Presenter mode's shared view (common/turntable_pose.js) against the C++ one
// (tests/golden/warp-vectors.json, written by WarpVectorsTest): a view comes
// back from its pose, and a pose is the same quaternion in both. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { kMaxZoom, kMinZoom, poseOfView, viewOfPose } from '../common/turntable_pose.js';
import { decodeFrame, encode } from '../protocol/messages.js';

test('a view shared as a pose comes back as the same view, through the codec too', () => {
  for (const [azimuth, elevation, zoom] of [[0, 0, 1], [30, 0, 1.5], [-170, 40, 0.5], [95, -80, 1]]) {
    const pose = poseOfView(azimuth, elevation, zoom, 7);
    for (const back of [viewOfPose(pose), viewOfPose(decodeFrame(encode(pose)))]) {
      assert.ok(Math.abs(back.azimuth - azimuth) < 1e-3, `${back.azimuth} for ${azimuth}`);
      assert.ok(Math.abs(back.elevation - elevation) < 1e-3, `${back.elevation} for ${elevation}`);
      assert.equal(back.zoom, zoom);
    }
  }
});

test('the pose is the C++ client\'s quaternion and a shared zoom is held to the C++ range', () => {
  const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).turntable;
  for (const { view: [azimuth, elevation, zoom], rotation } of golden.poses) {
    const pose = poseOfView(azimuth, elevation, zoom);
    rotation.forEach((v, i) => assert.ok(Math.abs(pose.rotation[i] - v) < 1e-6, `rotation[${i}] ${pose.rotation[i]} against ${v}`));
    assert.equal(pose.scale, zoom);
  }
  assert.deepEqual([kMinZoom, kMaxZoom], golden.zoom_range);
  for (const [scale, zoom] of golden.zoom_of_scale) assert.equal(viewOfPose({ rotation: [0, 0, 0, 1], scale }).zoom, Math.fround(zoom));
});
