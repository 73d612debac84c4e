#include "client/call/playout_delay.hpp"

#include <algorithm>

namespace inkwire {

Playout place_voice(double time_ms, double duration_ms, double arrived_ms, double played_ms, VoiceClock& clock) {
  if (!clock.offset_ms) clock.offset_ms = arrived_ms - time_ms;
  double skip = 0;
  if (const double sooner = *clock.offset_ms - (arrived_ms - time_ms); sooner >= kCatchUpMs) {
    skip = std::min(sooner, duration_ms);
    *clock.offset_ms -= skip;
    if (skip >= duration_ms) return {Playout::Kind::Skip};
  }
  const double at = time_ms + skip + *clock.offset_ms + clock.delay_ms;
  if (at >= played_ms) return {Playout::Kind::Play, at, skip};
  const double raised = clock.delay_ms + (played_ms - at) + kDelayMarginMs;
  if (raised > kMaxDelayMs) return {Playout::Kind::Late};
  clock.delay_ms = raised;
  return {Playout::Kind::Play, time_ms + skip + *clock.offset_ms + clock.delay_ms, skip};
}

}  // namespace inkwire
