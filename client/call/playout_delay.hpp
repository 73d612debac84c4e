#pragma once
// The jitter buffer's rule (SPEC F9): where a member's voice packet plays on this clock. A member's
// clock is mapped to this one by an offset taken at its first packet; the voice plays a delay
// behind that, starting at kStartDelayMs. A packet that comes after its moment has already played
// raises the delay by how late it was plus kDelayMarginMs, up to kMaxDelayMs, so a busy machine
// or a jittery network costs one short pause instead of a voice that breaks up packet after
// packet (on a loaded machine a fixed 80 ms dropped a fifth to a third of a call's packets). The
// delay never shrinks within a call: without stretching the sound that would cut words.
// The offset follows the quickest packets: a first packet that came slowly (a decoder starting, a
// busy moment) would otherwise add its lateness to every packet after it (measured in Chromium:
// 15-37 ms, a tenth of the mouth-to-ear budget). When a packet comes kCatchUpMs or more sooner
// than the offset expects, the offset moves that much nearer (at most the packet's length) and
// that much of the packet's start is not played: the part kept begins where the packets already
// placed end, and the next packet where it ends, so nothing overlaps or gaps.
// The browser's call/playout.js runs the same rule, pinned by tests/golden/warp-vectors.json
// ("playout").
#include <optional>

namespace inkwire {

inline constexpr double kStartDelayMs = 80, kDelayMarginMs = 20, kMaxDelayMs = 300, kCatchUpMs = 2;

// One member's mapping to this clock (ms).
struct VoiceClock {
  std::optional<double> offset_ms;  // this clock minus the member's; none before its first packet
  double delay_ms = kStartDelayMs;
};

struct Playout {
  enum class Kind { Play, Skip, Late } kind;
  double at_ms = 0;    // Play: where the part played begins
  double skip_ms = 0;  // Play: how much of the packet's start is not played
};

// Where a packet stamped `time_ms` on its member's clock and `duration_ms` long plays here, given
// when it `arrived_ms` and how far this clock has already played (`played_ms`): Play at a
// moment with what of its start is skipped, Skip (it came so soon that the offset moved its whole
// length nearer), or Late (later than even the largest delay allows). Updates `clock`.
Playout place_voice(double time_ms, double duration_ms, double arrived_ms, double played_ms, VoiceClock& clock);

}  // namespace inkwire
