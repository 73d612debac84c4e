#include "client/call/playout_delay.hpp"

namespace inkwire {

std::optional<double> playout_ms(double time_ms, double offset_ms, double& delay_ms, double now_ms) {
  const double at = time_ms + offset_ms + delay_ms;
  if (at >= now_ms) return at;
  const double raised = delay_ms + (now_ms - at) + kDelayMarginMs;
  if (raised > kMaxDelayMs) return std::nullopt;
  delay_ms = raised;
  return time_ms + offset_ms + delay_ms;
}

}  // namespace inkwire
