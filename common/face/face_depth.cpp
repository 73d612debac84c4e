#include "common/face/face_depth.hpp"

#include <algorithm>

namespace inkwire {
namespace {

// Features' depths by landmark (iBUG order), inter-ocular units; the jaw line (0-16) is computed.
constexpr std::array<float, kFaceLandmarks> kGenericDepth = {
    // 0-16 jaw line: from contour_depth()
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    // 17-21, 22-26 brows: outer ends over the outer eye corners, inner ends on the brow ridge
    -0.16f, 0.0f, 0.11f, 0.19f, 0.24f, 0.24f, 0.19f, 0.11f, 0.0f, -0.16f,
    // 27-30 the nose's bridge from the nasion to the tip; 31-35 its base, nostrils to the subnasal point
    0.29f, 0.43f, 0.54f, 0.67f, 0.22f, 0.32f, 0.38f, 0.32f, 0.22f,
    // 36-41, 42-47 eyes: corners behind the lids, which lie on the eyeball
    -0.16f, 0.0f, 0.06f, 0.11f, 0.06f, 0.0f, 0.11f, 0.06f, 0.0f, -0.16f, 0.0f, 0.06f,
    // 48-59 outer lips: corners level with the eyes, the middle of the lips standing out
    0.0f, 0.19f, 0.32f, 0.35f, 0.32f, 0.19f, 0.0f, 0.16f, 0.27f, 0.29f, 0.27f, 0.16f,
    // 60-67 inner lips
    0.0f, 0.25f, 0.29f, 0.25f, 0.0f, 0.22f, 0.25f, 0.22f};

constexpr float kChinDepth = 0.22f, kCurve = 0.83f, kDeepest = -1.1f;

}  // namespace

float contour_depth(float x) { return std::max(kChinDepth - kCurve * x * x, kDeepest); }

std::array<float, kFaceLandmarks> landmark_depths(const FaceLandmarks& face) {
  std::array<float, kFaceLandmarks> depth = kGenericDepth;
  for (int i = face_index::kJawFirst; i <= face_index::kJawLast; ++i) depth[size_t(i)] = contour_depth(face[size_t(i)].x);
  return depth;
}

}  // namespace inkwire
