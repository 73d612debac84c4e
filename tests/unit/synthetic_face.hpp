#pragma once
// A drawn face as 68 landmarks (iBUG order), for tests that need faces without photos: an oval
// jaw, arched brows, six-point eyes, a nose and two-contour lips, each part movable by the
// amounts the expression features measure (inter-ocular units, y down).
#include <cmath>

#include "common/face/face_shape.hpp"

namespace inkwire::test {

struct FacePose {
  float eye_open_left = 0.3f, eye_open_right = 0.3f;  // lid gap / eye width
  float brow_raise = 0.0f;       // both brows up
  float brow_inner_raise = 0.0f; // inner ends up (sad)
  float mouth_open = 0.0f;       // inner lips apart
  float mouth_widen = 0.0f;      // corners out, each side
  float corner_lift = 0.0f;      // corners up
  float jaw_drop = 0.0f;         // chin and lower lip down
};

// Landmarks of `pose` in the face frame, then placed in the image at `centre`, `scale` pixels
// between the eyes and rolled by `roll` radians.
inline FaceLandmarks synthetic_face(const FacePose& pose, glm::vec2 centre = {160, 120}, float scale = 60, float roll = 0) {
  FaceLandmarks p{};
  const float pi = 3.14159265f;
  for (int i = 0; i <= 16; ++i) {  // jaw: half an oval from temple to temple under the face
    const float a = pi * float(i) / 16.0f;
    const float down = std::sin(a);
    p[size_t(i)] = {-1.05f * std::cos(a), 0.25f + (1.35f + pose.jaw_drop) * down};
  }
  for (int side = 0; side < 2; ++side) {  // brows 17-21 (left), 22-26 (right)
    const float s = side == 0 ? -1.0f : 1.0f;
    for (int k = 0; k < 5; ++k) {
      const float t = float(k) / 4.0f;  // 0 = outer end for the left brow
      const float u = side == 0 ? t : 1.0f - t;
      const float x = s * (0.9f - 0.7f * u);
      const float arch = 0.08f * std::sin(pi * u);
      p[size_t(17 + side * 5 + k)] = {x, -0.45f - arch - pose.brow_raise - pose.brow_inner_raise * u};
    }
  }
  for (int k = 0; k < 4; ++k) p[size_t(27 + k)] = {0, 0.1f + 0.15f * float(k)};  // nose bridge to tip
  for (int k = 0; k < 5; ++k) p[size_t(31 + k)] = {-0.2f + 0.1f * float(k), 0.6f + (k == 2 ? 0.05f : 0.0f)};
  for (int side = 0; side < 2; ++side) {  // eyes: outer, upper x2, inner, lower x2 (left); mirrored order right
    const float cx = side == 0 ? -0.5f : 0.5f;
    const float gap = side == 0 ? pose.eye_open_left : pose.eye_open_right;
    const float half = 0.18f, lid = 0.5f * gap * 2 * half;  // lid offsets so that gap / width = eye_open
    const int b = side == 0 ? 36 : 42;
    const float outer = side == 0 ? -1.0f : 1.0f;  // 36 is the left eye's outer corner; 42 the right eye's inner one
    const float first = side == 0 ? outer : -outer;
    p[size_t(b + 0)] = {cx + first * half, 0};
    p[size_t(b + 1)] = {cx + first * half / 3, -lid};
    p[size_t(b + 2)] = {cx - first * half / 3, -lid};
    p[size_t(b + 3)] = {cx - first * half, 0};
    p[size_t(b + 4)] = {cx - first * half / 3, lid};
    p[size_t(b + 5)] = {cx + first * half / 3, lid};
  }
  const float half_width = 0.42f + pose.mouth_widen, y = 1.0f, lip = 0.07f;
  const float corner_y = y - pose.corner_lift, open = 0.5f * pose.mouth_open, drop = pose.jaw_drop;
  const glm::vec2 outer[12] = {{-half_width, corner_y},       {-0.28f, y - lip - 0.02f}, {-0.12f, y - lip - open * 0.2f - 0.04f},
                               {0, y - lip - 0.03f},          {0.12f, y - lip - 0.04f},  {0.28f, y - lip - 0.02f},
                               {half_width, corner_y},        {0.28f, y + lip + open + drop}, {0.12f, y + lip + open + drop + 0.02f},
                               {0, y + lip + open + drop + 0.03f}, {-0.12f, y + lip + open + drop + 0.02f}, {-0.28f, y + lip + open + drop}};
  for (int k = 0; k < 12; ++k) p[size_t(48 + k)] = outer[k];
  const glm::vec2 inner[8] = {{-half_width + 0.06f, corner_y}, {-0.12f, y - open}, {0, y - open}, {0.12f, y - open},
                              {half_width - 0.06f, corner_y},  {0.12f, y + open + drop}, {0, y + open + drop}, {-0.12f, y + open + drop}};
  for (int k = 0; k < 8; ++k) p[size_t(60 + k)] = inner[k];

  const float c = std::cos(roll), s = std::sin(roll);
  for (glm::vec2& q : p) q = centre + scale * glm::vec2(c * q.x - s * q.y, s * q.x + c * q.y);
  return p;
}

}  // namespace inkwire::test
