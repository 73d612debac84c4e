// When a call member's voice packet plays (SPEC F9, F15): the jitter rule of
// client/call/playout_delay.hpp, operation for operation, pinned by the golden "playout" vectors
// (tests/golden/warp-vectors.json, checked by client/web/test/voice.test.js). Imported by the
// playout worklet (call/playout_worklet.js), which applies it on the audio thread: no global
// of a page or a worker is used here.

export const kStartDelayMs = 80, kDelayMarginMs = 20, kMaxDelayMs = 300;

// Where a packet stamped `timeMs` on its member's clock plays on this one (ms), given `offsetMs`
// (this clock minus the member's, from its first packet), `member.delayMs` (raised here when the
// packet is late) and `nowMs`, how far this clock has played: null when the packet is later than
// even the largest delay allows.
export function playoutMs(timeMs, offsetMs, member, nowMs) {
  const at = timeMs + offsetMs + member.delayMs;
  if (at >= nowMs) return at;
  const raised = member.delayMs + (nowMs - at) + kDelayMarginMs;
  if (raised > kMaxDelayMs) return null;
  member.delayMs = raised;
  return timeMs + offsetMs + member.delayMs;
}
