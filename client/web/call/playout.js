// When a call member's voice packet plays (SPEC F9, F15): the jitter rule of
// client/call/playout_delay.hpp, operation for operation, pinned by the golden "playout" vectors
// (tests/golden/warp-vectors.json, checked by client/web/test/voice.test.js). Imported by the
// playout worklet (call/playout_worklet.js), which applies it on the audio thread: no global
// of a page or a worker is used here.

export const kStartDelayMs = 80, kDelayMarginMs = 20, kMaxDelayMs = 300, kCatchUpMs = 2;

// A member's mapping to this clock: {offsetMs (this clock minus the member's; null before its
// first packet), delayMs}.
export function voiceClock() {
  return { offsetMs: null, delayMs: kStartDelayMs };
}

// Where a packet stamped `timeMs` on its member's clock and `durationMs` long plays here, given
// when it `arrivedMs` and how far this clock has played (`playedMs`): {kind: 'play', atMs,
// skipMs} (where the part played begins, how much of its start is not played), {kind: 'skip'}
// (the offset moved its whole length nearer) or {kind: 'late'} (later than even the largest
// delay allows). Updates `clock`.
export function placeVoice(timeMs, durationMs, arrivedMs, playedMs, clock) {
  if (clock.offsetMs === null) clock.offsetMs = arrivedMs - timeMs;
  let skip = 0;
  const sooner = clock.offsetMs - (arrivedMs - timeMs);
  if (sooner >= kCatchUpMs) {
    skip = Math.min(sooner, durationMs);
    clock.offsetMs -= skip;
    if (skip >= durationMs) return { kind: 'skip' };
  }
  const at = timeMs + skip + clock.offsetMs + clock.delayMs;
  if (at >= playedMs) return { kind: 'play', atMs: at, skipMs: skip };
  const raised = clock.delayMs + (playedMs - at) + kDelayMarginMs;
  if (raised > kMaxDelayMs) return { kind: 'late' };
  clock.delayMs = raised;
  return { kind: 'play', atMs: timeMs + skip + clock.offsetMs + clock.delayMs, skipMs: skip };
}
