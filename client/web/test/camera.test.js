// The browser's face-video rectangle against the C++ client's (tests/golden/warp-vectors.json,
// "face_crop", written by WarpVectorsTest): the same reports give the same rectangles and the
// same key frames. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { followFace, kFaceSearchWidth, kFaceVideoSide, searchPictureSize } from '../call/camera.js';

test('the crop follows every report and one that jumps starts again, as in C++', () => {
  const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).face_crop;
  assert.deepEqual([kFaceVideoSide, kFaceSearchWidth], golden.sides);
  for (const step of golden.steps) {
    const choice = followFace(step.shown, step.reported, 640, 480);
    assert.deepEqual(choice.region, step.region, JSON.stringify(step));
    assert.equal(choice.jumped, step.jumped, JSON.stringify(step));
  }
});

test('the whole frame is sent at the size C++ sends it, neither side past the search width (a portrait camera too)', () => {
  const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).face_crop;
  assert.ok(golden.search_pictures.length > 0);
  for (const { frame, picture } of golden.search_pictures) {
    assert.deepEqual(searchPictureSize(frame[0], frame[1]), picture, JSON.stringify(frame));
    assert.ok(Math.max(...picture) <= kFaceSearchWidth, JSON.stringify(picture));
  }
});
