// The browser's jitter buffer against the C++ client's (tests/golden/warp-vectors.json, "playout",
// written by WarpVectorsTest): the same packets, the same clock, the same places to play and the
// same delays. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { kDelayMarginMs, kMaxDelayMs, kStartDelayMs, playoutMs } from '../call/playout.js';

test('a late packet raises the delay and plays, one beyond the largest delay is dropped, as in C++', () => {
  const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).playout;
  assert.deepEqual([kStartDelayMs, kDelayMarginMs, kMaxDelayMs], golden.limits);
  const member = { delayMs: kStartDelayMs };
  for (const step of golden.steps) {
    assert.equal(playoutMs(step.time_ms, golden.offset_ms, member, step.now_ms), step.at_ms, `packet ${step.time_ms}`);
    assert.equal(member.delayMs, step.delay_ms, `delay after packet ${step.time_ms}`);
  }
});
