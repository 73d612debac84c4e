// The browser's jitter buffer against the C++ client's (tests/golden/warp-vectors.json, "playout",
// written by WarpVectorsTest): the same packets, the same clock, the same places to play, the same
// skips and the same offsets and delays. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { kCatchUpMs, kDelayMarginMs, kMaxDelayMs, kStartDelayMs, placeVoice, voiceClock } from '../call/playout.js';

test('quick packets move the offset nearer, late ones raise the delay, one beyond the largest is late, as in C++', () => {
  const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).playout;
  assert.deepEqual([kStartDelayMs, kDelayMarginMs, kMaxDelayMs, kCatchUpMs], golden.limits);
  const clock = voiceClock();
  for (const step of golden.steps) {
    const placed = placeVoice(step.time_ms, step.duration_ms, step.arrived_ms, step.played_ms, clock);
    assert.equal(placed.kind, step.kind, `packet ${step.time_ms}`);
    if (placed.kind === 'play') {
      assert.equal(placed.atMs, step.at_ms, `packet ${step.time_ms}`);
      assert.equal(placed.skipMs, step.skip_ms, `packet ${step.time_ms}`);
    }
    assert.equal(clock.offsetMs, step.offset_ms, `offset after packet ${step.time_ms}`);
    assert.equal(clock.delayMs, step.delay_ms, `delay after packet ${step.time_ms}`);
  }
});
