#include "server/face/face_features.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "common/luminance.hpp"

namespace inkwire {

using namespace face_index;

namespace {

float mean_y(const FaceLandmarks& p, int first, int last) {
  float sum = 0;
  for (int i = first; i <= last; ++i) sum += p[size_t(i)].y;
  return sum / float(last - first + 1);
}

float eye_openness(const FaceLandmarks& p, int first) {
  const auto at = [&](int k) { return p[size_t(first + k)]; };
  const float gap = 0.5f * (glm::distance(at(1), at(5)) + glm::distance(at(2), at(4)));
  return gap / glm::distance(at(0), at(3));
}

// The standard deviation of luma in a box centred on the eye, its width corner to corner and its
// height half that.
float eye_shade(const Image& frame, const FaceLandmarks& p, int first) {
  float x0 = p[size_t(first)].x, x1 = x0, cy = 0;
  for (int k = 0; k < 6; ++k) {
    const glm::vec2 q = p[size_t(first + k)];
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), cy += q.y / 6.0f;
  }
  const float half = 0.25f * (x1 - x0);
  const int left = std::max(0, int(x0)), right = std::min(frame.width - 1, int(x1));
  const int top = std::max(0, int(cy - half)), bottom = std::min(frame.height - 1, int(cy + half));
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int y = top; y <= bottom; ++y)
    for (int x = left; x <= right; ++x) {
      const uint8_t* c = frame.at(x, y);
      const double luma = rec601_luma<double>(c[0], c[1], c[2]);
      sum += luma, sum2 += luma * luma, ++n;
    }
  if (n < 4) return 0.0f;
  const double mean = sum / n;
  return float(std::sqrt(std::max(sum2 / n - mean * mean, 0.0)));
}

}  // namespace

FaceFeatures measure_features(const FaceLandmarks& landmarks, const Image* frame) {
  const FaceLandmarks p = to_face(landmarks, face_frame(landmarks));
  FaceFeatures f;
  f.brow_raise_left = -mean_y(p, kBrowLeftFirst, kBrowLeftLast);
  f.brow_raise_right = -mean_y(p, kBrowRightFirst, kBrowRightLast);
  // Inner ends (21, 22) against outer ends (17, 26): y is down, so inner-up makes this positive.
  f.brow_inner_raise = 0.5f * ((p[17].y + p[26].y) - (p[21].y + p[22].y));
  f.eye_open_left = eye_openness(p, kEyeLeftFirst);
  f.eye_open_right = eye_openness(p, kEyeRightFirst);
  f.mouth_open = (glm::distance(p[61], p[67]) + glm::distance(p[62], p[66]) + glm::distance(p[63], p[65])) / 3.0f;
  f.mouth_width = glm::distance(p[kMouthLeft], p[kMouthRight]);
  const float midline = 0.5f * (p[kLipTop].y + p[kLipBottom].y);
  f.corner_lift = midline - 0.5f * (p[kMouthLeft].y + p[kMouthRight].y);
  f.jaw_drop = p[kChin].y - p[kNoseTip].y;
  if (frame) {
    f.eye_shade_left = eye_shade(*frame, landmarks, kEyeLeftFirst);
    f.eye_shade_right = eye_shade(*frame, landmarks, kEyeRightFirst);
  }
  return f;
}

FaceFeatures operator+(const FaceFeatures& a, const FaceFeatures& b) {
  return {a.brow_raise_left + b.brow_raise_left, a.brow_raise_right + b.brow_raise_right, a.eye_open_left + b.eye_open_left,
          a.eye_open_right + b.eye_open_right,   a.mouth_open + b.mouth_open,             a.mouth_width + b.mouth_width,
          a.corner_lift + b.corner_lift,         a.jaw_drop + b.jaw_drop,                 a.brow_inner_raise + b.brow_inner_raise,
          a.eye_shade_left + b.eye_shade_left,   a.eye_shade_right + b.eye_shade_right};
}

FaceFeatures operator*(float s, const FaceFeatures& f) {
  return {s * f.brow_raise_left, s * f.brow_raise_right, s * f.eye_open_left, s * f.eye_open_right, s * f.mouth_open,
          s * f.mouth_width,     s * f.corner_lift,      s * f.jaw_drop,      s * f.brow_inner_raise,
          s * f.eye_shade_left,  s * f.eye_shade_right};
}

}  // namespace inkwire
