#include "server/face/expression_stream.hpp"

#include "protocol/framing.hpp"

namespace inkwire {

std::optional<protocol::ExpressionCode> ExpressionStream::next(ExpressionState state, double now) {
  if (last_ && *last_ == state && now - last_time_ < keepalive_) return std::nullopt;
  last_ = state;
  last_time_ = now;
  protocol::ExpressionCode message;
  message.code = uint8_t(state.expression);
  message.intensity = state.intensity;
  message.sequence = sequence_++;
  bytes_ += protocol::encoded_size(message);
  ++messages_;
  return message;
}

}  // namespace inkwire
