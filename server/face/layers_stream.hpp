#pragma once
// A member's face on the wire (SPEC F20-F22): member-layers when what the face shows changes
// (a layer's code, its intensity by a step, an eye's openness by a step, the head turned
// kPoseStep degrees) and otherwise once every `keepalive` seconds, so a late or lossy receiver
// converges; at most kPerSecond a second on average, kBurst at once (a blink is two in 150 ms):
// a change that finds no room goes with the next picture that does, as it then is. 22 bytes
// each, so at most 0.9 kbit/s (SPEC F21: 1). Counts what it sends in framed bytes. The receiver
// tweens each change over ~100 ms.
#include <cstdint>
#include <optional>

#include "common/face/face_layers.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class LayersStream {
 public:
  static constexpr float kPoseStep = 3;        // degrees a head must turn before it is sent again
  static constexpr int kIntensityStep = 16;    // of 255, as the single code's stream steps
  static constexpr int kEyeStep = 15;          // percent of the neutral photo's openness
  static constexpr double kPerSecond = 5, kBurst = 3;

  explicit LayersStream(double keepalive_seconds = 2.0) : keepalive_(keepalive_seconds) {}

  // The message to send for `state` at time `now` (seconds; the message says `time_ms`), if any.
  std::optional<protocol::MemberLayers> next(const FaceState& state, double now, uint16_t member, uint32_t time_ms,
                                             protocol::FaceSource source = protocol::FaceSource::Camera);

  uint64_t bytes() const { return bytes_; }  // framed bytes of every message so far
  uint64_t messages() const { return messages_; }

 private:
  bool changed(const FaceState& state) const;
  double keepalive_;
  std::optional<FaceState> last_;  // as sent (the wire's whole degrees)
  double last_time_ = 0;
  double room_ = kBurst, room_at_ = 0;  // messages that may go now, as of room_at_
  uint64_t bytes_ = 0, messages_ = 0;
};

// A face state as the wire carries it: the pose in whole degrees within +-90.
protocol::MemberLayers member_layers(const FaceState& state, uint16_t member, uint32_t time_ms, protocol::FaceSource source);

}  // namespace inkwire
