#pragma once
// The jitter buffer's delay (SPEC F9): how far behind its member's clock a voice plays here. It
// starts at kStartDelayMs; a packet that comes after its moment has already played raises it by
// how late the packet was plus kDelayMarginMs, up to kMaxDelayMs, so a busy machine or a jittery
// network costs one short pause instead of a voice that breaks up packet after packet (on a
// loaded machine a fixed 80 ms dropped a fifth to a third of a call's packets). It never shrinks
// within a call: without stretching the sound that would cut words. The browser's voice.js runs
// the same rule, pinned by tests/golden/warp-vectors.json ("playout").
#include <optional>

namespace inkwire {

inline constexpr double kStartDelayMs = 80, kDelayMarginMs = 20, kMaxDelayMs = 300;

// Where a packet stamped `time_ms` on its member's clock plays on this one (ms), given
// `offset_ms` (this clock minus the member's, taken at its first packet), the member's
// `delay_ms` (raised here when the packet is late) and `now_ms`, how far this clock has already
// played: nothing when the packet is later than even the largest delay allows.
std::optional<double> playout_ms(double time_ms, double offset_ms, double& delay_ms, double now_ms);

}  // namespace inkwire
