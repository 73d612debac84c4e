// Voice frames stamped from the capture's own times (call/capture_clock.js), not the encoder's
// sample count: a gap in the capture shows in the stamps. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { CaptureClock } from '../call/capture_clock.js';

test('each 60 ms frame is stamped when its first sample was heard, across a gap the capture lost', () => {
  const clock = new CaptureClock(48000);
  let heard = 1000;
  for (let i = 0; i < 30; ++i) {
    if (i === 12) heard += 500;  // the capture lost half a second: the audio thread stalled
    clock.fed(heard, 960);       // 20 ms chunks
    heard += 20;
  }
  const stamps = Array.from({ length: 10 }, () => clock.frame(60));
  // Chunks 0-11 were heard at 1000-1220 and chunks 12-29 at 1740-2080: frames 0-3 lie in the
  // first run, the rest in the second.
  assert.deepEqual(stamps, [1000, 1060, 1120, 1180, 1740, 1800, 1860, 1920, 1980, 2040]);
});

test('a frame starting inside a chunk takes its place in that chunk; nothing fed, no stamp', () => {
  assert.equal(new CaptureClock(48000).frame(60), null);
  const clock = new CaptureClock(48000);
  clock.fed(500, 2000);  // 41.67 ms chunks, as a capture at another size would give
  clock.fed(541.6666666666667, 2000);
  clock.fed(583.3333333333334, 2000);
  clock.frame(60);
  assert.ok(Math.abs(clock.frame(60) - 560) < 1e-9);  // the 2880th sample: 880 into the second chunk
});
