#pragma once
// A member's face across protocol versions (protocol/SPEC.md, "Versioning"). Version 9 sends
// member-layers: the layers and the head's pose (SPEC F20-F22). A peer of version 7 or 8 reads only
// member-face, one code: it is sent the code that says most of what the layers show
// (common/face/face_layers.hpp dominant_expression), and still draws expressions, without blinks
// or a smile while talking. A member-face from such a peer or recording reads as layers.
// Header-only: the server and the clients, which link common/, use it.
#include <algorithm>

#include "common/face/face_layers.hpp"
#include "protocol/messages.hpp"

namespace inkwire::protocol {

inline MemberFace member_face_of(const MemberLayers& m) {
  const ExpressionState shown =
      dominant_expression({.expression = m.expression, .mouth = m.mouth, .eye_left = m.eye_left, .eye_right = m.eye_right});
  return {.member = m.member, .time_ms = m.time_ms, .expression = {.code = uint8_t(shown.expression), .intensity = shown.intensity},
          .yaw = m.yaw, .pitch = m.pitch, .roll = m.roll, .source = m.source};
}

// Codes a version-7 sender did not know read as neutral; poses past +-90 degrees as +-90.
inline MemberLayers member_layers_of(const MemberFace& m) {
  const FaceLayers layers = layers_of(expression_state(m.expression).value_or(ExpressionState{}));
  const auto degrees = [](int8_t v) { return int8_t(std::clamp(int(v), -kMaxPoseDegrees, kMaxPoseDegrees)); };
  return {.member = m.member, .time_ms = m.time_ms, .yaw = degrees(m.yaw), .pitch = degrees(m.pitch), .roll = degrees(m.roll),
          .expression = layers.expression, .mouth = layers.mouth, .eye_left = layers.eye_left, .eye_right = layers.eye_right,
          .source = m.source};
}

// The layers and pose a member-layers message says, as the face renderers take them.
inline FaceState face_state_of(const MemberLayers& m) {
  return {.layers = {.expression = m.expression, .mouth = m.mouth, .eye_left = m.eye_left, .eye_right = m.eye_right},
          .pose = {.yaw = float(m.yaw), .pitch = float(m.pitch), .roll = float(m.roll)}};
}

}  // namespace inkwire::protocol
