#pragma once
// The expression stream (SPEC F4): only codes go over the wire, a message when the expression
// or its intensity changes and otherwise one keep-alive a second, so a late or lossy receiver
// converges. Counts what it sends in framed bytes.
#include <cstdint>
#include <optional>

#include "common/face/expression.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class ExpressionStream {
 public:
  explicit ExpressionStream(double keepalive_seconds = 1.0) : keepalive_(keepalive_seconds) {}

  // The message to send for this frame's state at time `now` (seconds), if any.
  std::optional<protocol::ExpressionCode> next(ExpressionState state, double now);

  uint64_t bytes() const { return bytes_; }      // framed bytes of every message so far
  uint64_t messages() const { return messages_; }

 private:
  double keepalive_;
  std::optional<ExpressionState> last_;
  double last_time_ = 0;
  uint16_t sequence_ = 0;
  uint64_t bytes_ = 0, messages_ = 0;
};

}  // namespace inkwire
