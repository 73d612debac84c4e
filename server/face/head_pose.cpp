#include "server/face/head_pose.hpp"

#include <array>
#include <cmath>
#include <complex>

#include "common/face/face_depth.hpp"

namespace inkwire {
namespace {

using Complex = std::complex<double>;

// The rigid points: eye corners, the nose's bridge and base.
constexpr std::array<int, 13> kRigid = {36, 39, 42, 45, 27, 28, 29, 30, 31, 32, 33, 34, 35};
constexpr double kDegrees = 57.29577951308232;
constexpr float kMaxTurn = 70;

struct Fit {
  double residual = 1e300;
  double roll = 0;  // radians, of the face frame in the image
};

// The best 2D similarity from the head turned by yaw and pitch (face frame) to the frame's points
// (complex numbers: the optimal scale-and-rotation is one complex factor), and what is left.
Fit fit(const std::array<glm::vec3, kRigid.size()>& head, const std::array<Complex, kRigid.size()>& seen, float yaw, float pitch) {
  const glm::mat3 rotation = rotation_of({.yaw = yaw, .pitch = pitch, .roll = 0});
  std::array<Complex, kRigid.size()> drawn;
  Complex mean_drawn = 0, mean_seen = 0;
  for (size_t k = 0; k < kRigid.size(); ++k) {
    const glm::vec3 p = turned(head[k], rotation);
    drawn[k] = {p.x, p.y};
    mean_drawn += drawn[k], mean_seen += seen[k];
  }
  mean_drawn /= double(kRigid.size()), mean_seen /= double(kRigid.size());
  Complex cross = 0;
  double drawn_norm = 0, seen_norm = 0;
  for (size_t k = 0; k < kRigid.size(); ++k) {
    const Complex a = drawn[k] - mean_drawn, b = seen[k] - mean_seen;
    cross += std::conj(a) * b;
    drawn_norm += std::norm(a), seen_norm += std::norm(b);
  }
  if (drawn_norm <= 0) return {};
  return {.residual = seen_norm - std::norm(cross) / drawn_norm, .roll = std::arg(cross)};
}

}  // namespace

HeadPose head_pose(const FaceLandmarks& face, const FaceLandmarks& neutral) {
  const FaceFrame rest = face_frame(neutral);
  const FaceLandmarks neutral_face = to_face(neutral, rest);
  const std::array<float, kFaceLandmarks> depth = landmark_depths(neutral_face);
  std::array<glm::vec3, kRigid.size()> head;
  std::array<Complex, kRigid.size()> seen;
  for (size_t k = 0; k < kRigid.size(); ++k) {
    const size_t i = size_t(kRigid[k]);
    head[k] = glm::vec3(neutral_face[i], depth[i]);
    seen[k] = {face[i].x, face[i].y};
  }
  // Coarse to fine over yaw and pitch: every 2 degrees, then every quarter about the best.
  float best_yaw = 0, best_pitch = 0;
  Fit best = fit(head, seen, 0, 0);
  for (float step : {2.0f, 0.25f}) {
    const float yaw0 = best_yaw, pitch0 = best_pitch, reach = step == 2.0f ? kMaxTurn : 2.0f;
    for (float yaw = yaw0 - reach; yaw <= yaw0 + reach + 1e-3f; yaw += step)
      for (float pitch = pitch0 - reach; pitch <= pitch0 + reach + 1e-3f; pitch += step) {
        if (std::abs(yaw) > kMaxTurn || std::abs(pitch) > kMaxTurn) continue;
        const Fit f = fit(head, seen, yaw, pitch);
        if (f.residual < best.residual) best = f, best_yaw = yaw, best_pitch = pitch;
      }
  }
  // The similarity's rotation is the neutral face's own tilt in its photo plus the head's roll.
  const double roll = (best.roll - std::atan2(double(rest.axis.y), double(rest.axis.x))) * kDegrees;
  return {.yaw = best_yaw, .pitch = best_pitch, .roll = float(std::remainder(roll, 360.0))};
}

}  // namespace inkwire
