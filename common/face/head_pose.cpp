#include "common/face/head_pose.hpp"

#include <cmath>

namespace inkwire {

glm::mat3 rotation_of(const HeadPose& pose) {
  constexpr float kRadians = 0.017453293f;
  const float y = pose.yaw * kRadians, p = pose.pitch * kRadians, r = pose.roll * kRadians;
  // Columns (GLM is column-major). x right, y down, z towards the camera.
  // Yaw: a point in front (z > 0) goes right (x grows) as the face turns right.
  const glm::mat3 yaw(std::cos(y), 0, -std::sin(y), 0, 1, 0, std::sin(y), 0, std::cos(y));
  // Pitch: a point in front goes up (y falls) as the face looks up.
  const glm::mat3 pitch(1, 0, 0, 0, std::cos(p), std::sin(p), 0, -std::sin(p), std::cos(p));
  // Roll: the eye line (x) turns towards y (down on screen), clockwise as one looks at it.
  const glm::mat3 roll(std::cos(r), std::sin(r), 0, -std::sin(r), std::cos(r), 0, 0, 0, 1);
  return roll * pitch * yaw;
}

glm::vec3 turned(glm::vec3 point, const glm::mat3& rotation) { return kNeckPivot + rotation * (point - kNeckPivot); }

HeadPose mix(const HeadPose& a, const HeadPose& b, float t) {
  return {a.yaw + (b.yaw - a.yaw) * t, a.pitch + (b.pitch - a.pitch) * t, a.roll + (b.roll - a.roll) * t};
}

}  // namespace inkwire
