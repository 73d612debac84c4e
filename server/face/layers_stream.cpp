#include "server/face/layers_stream.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "protocol/face_versions.hpp"
#include "protocol/framing.hpp"

namespace inkwire {
namespace {

int8_t degrees_byte(float degrees) {
  return int8_t(std::clamp(std::lround(degrees), -long(protocol::kMaxPoseDegrees), long(protocol::kMaxPoseDegrees)));
}

bool layer_changed(const ExpressionState& a, const ExpressionState& b) {
  return a.expression != b.expression || std::abs(int(a.intensity) - int(b.intensity)) >= LayersStream::kIntensityStep;
}

}  // namespace

protocol::MemberLayers member_layers(const FaceState& s, uint16_t member, uint32_t time_ms, protocol::FaceSource source) {
  return {.member = member, .time_ms = time_ms, .yaw = degrees_byte(s.pose.yaw), .pitch = degrees_byte(s.pose.pitch), .roll = degrees_byte(s.pose.roll),
          .expression = s.layers.expression, .mouth = s.layers.mouth, .eye_left = std::min(s.layers.eye_left, kMaxEyeOpenness),
          .eye_right = std::min(s.layers.eye_right, kMaxEyeOpenness), .source = source};
}

bool LayersStream::changed(const FaceState& s) const {
  const FaceState& l = *last_;
  return layer_changed(s.layers.expression, l.layers.expression) || layer_changed(s.layers.mouth, l.layers.mouth) ||
         std::abs(int(s.layers.eye_left) - int(l.layers.eye_left)) >= kEyeStep ||
         std::abs(int(s.layers.eye_right) - int(l.layers.eye_right)) >= kEyeStep || std::abs(s.pose.yaw - l.pose.yaw) >= kPoseStep ||
         std::abs(s.pose.pitch - l.pose.pitch) >= kPoseStep || std::abs(s.pose.roll - l.pose.roll) >= kPoseStep;
}

std::optional<protocol::MemberLayers> LayersStream::next(const FaceState& state, double now, uint16_t member, uint32_t time_ms,
                                                         protocol::FaceSource source) {
  if (last_ && !changed(state) && now - last_time_ < keepalive_) return std::nullopt;
  room_ = std::min(kBurst, room_ + (now - room_at_) * kPerSecond);
  room_at_ = now;
  if (room_ < 1.0) return std::nullopt;
  room_ -= 1.0;
  const protocol::MemberLayers message = member_layers(state, member, time_ms, source);
  last_ = protocol::face_state_of(message);
  last_time_ = now;
  bytes_ += protocol::encoded_size(message);
  ++messages_;
  return message;
}

}  // namespace inkwire
