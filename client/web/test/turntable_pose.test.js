// Presenter mode's shared view (common/turntable_pose.js) against the C++ one
// (TurntableOrbitTest in tests/e2e/turntable_e2e_test.cpp checks the same numbers): a view comes
// back from its pose, and a pose is the same quaternion in both. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { poseOfView, viewOfPose } from '../common/turntable_pose.js';
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

test('the pose is the C++ client\'s quaternion', () => {
  const { rotation, scale } = poseOfView(30, 20, 1.5);
  [0.167731, -0.254887, -0.044943, 0.951251].forEach((v, i) => assert.ok(Math.abs(rotation[i] - v) < 1e-6, `rotation[${i}] ${rotation[i]}`));
  assert.equal(scale, 1.5);
});
