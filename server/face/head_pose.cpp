#include "server/face/head_pose.hpp"

#include <algorithm>
#include <cmath>

namespace inkwire {
namespace {

constexpr float kNoseDepth = 0.6f;  // nose tip in front of the eye line, in inter-ocular units
constexpr float kDegrees = 57.29578f;

float turned(float moved) { return std::asin(std::clamp(moved / kNoseDepth, -1.0f, 1.0f)) * kDegrees; }

}  // namespace

HeadPose head_pose(const FaceLandmarks& face, const FaceLandmarks& neutral) {
  const FaceFrame now = face_frame(face), rest = face_frame(neutral);
  // The nose tip in each face's own frame (origin between the eyes, unrolled, one unit between them).
  const glm::vec2 nose = now.to_face(face[face_index::kNoseTip]), nose_at_rest = rest.to_face(neutral[face_index::kNoseTip]);
  const float roll = (std::atan2(now.axis.y, now.axis.x) - std::atan2(rest.axis.y, rest.axis.x)) * kDegrees;
  return {.yaw = turned(nose.x - nose_at_rest.x), .pitch = -turned(nose.y - nose_at_rest.y), .roll = std::remainder(roll, 360.0f)};
}

}  // namespace inkwire
