// The page's session connection (net/session.js) against the native client's
// (client/net/session_client.hpp): how many asset chunks it asks for at once and how long a
// silent server is waited for (tests/golden/warp-vectors.json "session", written by
// WarpVectorsTest). Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { kRequestsAhead, kServerSilenceMs } from '../net/session.js';

const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/warp-vectors.json', import.meta.url))).session;

test('the page asks as far ahead and waits for a silent server as long as the native client', () => {
  assert.equal(kRequestsAhead, golden.requests_ahead);
  assert.equal(kServerSilenceMs, golden.server_silence_ms);
});
