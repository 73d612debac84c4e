#include "common/face/face_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <glm/geometric.hpp>

#include "common/face/face_depth.hpp"
#include "common/face/face_shape.hpp"

namespace inkwire {

namespace {

constexpr float kClosedMouthGap = 0.04f;  // inner lips closer than this (inter-ocular) count as closed
constexpr float kCavityDepth = 0.15f;     // the mouth's inside lies behind the lips: a turned face's lips hide it

// Anchors around the face (face frame, with depth), and how much each turns with the head:
//   the forehead, the brows lifted to the hairline, and the head's outline over the hair and
//   down past the ears (an ellipse a fifth wider than the jaw line, reaching 1.8 eye distances
//   above the brows): they turn with the head, so the hair goes with the face;
//   the neck, the jaw line pushed out from the face centre: half way, as a neck turns under a
//   head;
// the image border stays. The expression's deformation fades out between the landmarks and them,
// and an opening jaw (up to ~0.35 inter-ocular) cannot fold over them.
struct Anchor {
  glm::vec3 point;
  float follows;
};

std::vector<Anchor> face_anchors(const FaceLandmarks& face) {
  std::vector<Anchor> anchors;
  // The forehead: over the brows' ends, their middles and between them.
  for (const auto& [a, b, depth] : {std::tuple{17, 17, -0.25f}, std::tuple{19, 19, 0.05f}, std::tuple{21, 22, 0.25f}, std::tuple{24, 24, 0.05f},
                                    std::tuple{26, 26, -0.25f}})
    anchors.push_back({glm::vec3(0.5f * (face[size_t(a)] + face[size_t(b)]) + glm::vec2(0.0f, -0.8f), depth), 1.0f});
  // The head's outline: its centre level with the brows' top, on the head's widest (the skull's
  // centre, 1.3 behind the eyes: its outline seen from the front lies there).
  const float brows = std::min(face[19].y, face[24].y);
  const float half_width = 1.2f * 0.5f * (face[16].x - face[0].x), centre_x = 0.5f * (face[16].x + face[0].x);
  const float half_height = 1.8f, centre_y = brows;
  for (int k = 0; k <= 6; ++k) {
    const float angle = 3.14159265f * float(k) / 6.0f;
    anchors.push_back({{centre_x + half_width * std::cos(angle), centre_y - half_height * std::sin(angle), -1.3f}, 1.0f});
  }
  for (float side : {-1.0f, 1.0f}) anchors.push_back({{centre_x + side * half_width, 0.5f * (face[0].y + face[16].y) + 0.4f, -1.1f}, 1.0f});
  // The neck: the lower jaw line pushed out from the face centre.
  const glm::vec2 centre{0.0f, 0.45f};
  for (int i = 0; i <= 16; i += 2) anchors.push_back({glm::vec3(centre + 1.6f * (face[size_t(i)] - centre), -0.9f), 0.5f});
  return anchors;
}

bool inside(const std::vector<glm::vec2>& polygon, glm::vec2 p) {  // even-odd rule
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

}  // namespace

FaceMesh build_face_mesh(const FaceLandmarks& landmarks, const ExpressionTemplates& templates, int width, int height) {
  const FaceFrame frame = face_frame(landmarks);
  const FaceLandmarks face = to_face(landmarks, frame);
  FaceMesh out;

  // Points: the 68 landmarks, the anchors, the image border.
  std::vector<glm::vec2> points(landmarks.begin(), landmarks.end());
  const std::array<float, kFaceLandmarks> depth = landmark_depths(face);
  for (int i = 0; i < kFaceLandmarks; ++i) {
    out.landmark_of.push_back(i);
    out.head_point.push_back(glm::vec3(face[size_t(i)], depth[size_t(i)]));
    out.follows.push_back(1.0f);
  }
  // Anchors near or past the image edge are left out (the border points hold the frame there);
  // squeezed against the edge they would make sliver triangles the triangulation can miss.
  const float margin = 0.04f * float(std::min(width, height));
  for (const Anchor& anchor : face_anchors(face)) {
    const glm::vec2 a = frame.to_image(glm::vec2(anchor.point));
    if (!(a.x > margin && a.y > margin && a.x < float(width) - margin && a.y < float(height) - margin)) continue;
    points.push_back(a);
    out.head_point.push_back(anchor.point);
    out.follows.push_back(anchor.follows);
  }
  for (const glm::vec2& b : border_points(width, height)) {
    points.push_back(b);
    out.head_point.push_back(glm::vec3(frame.to_face(b), 0.0f));
    out.follows.push_back(0.0f);
  }
  out.landmark_of.resize(points.size(), -1);

  // Triangulated with the mouth open, so the inner lips are apart and the triangles between
  // them exist (closed, they nearly coincide); those inside the inner lips are the cavity.
  std::vector<glm::vec2> layout = points;
  const FaceLandmarks open = apply_expression(landmarks, templates, {Expression::VisemeOpen, 255});
  for (int i = 0; i < kFaceLandmarks; ++i) layout[size_t(i)] = open[size_t(i)];
  const auto triangles = delaunay_triangles(layout);
  const std::vector<glm::vec2> inner_lips(open.begin() + 60, open.begin() + 68);
  // A photo whose mouth is already open (teeth showing) has an inside to stretch; only a
  // closed one needs the cavity colour.
  const float gap = (glm::distance(face[61], face[67]) + glm::distance(face[62], face[66]) + glm::distance(face[63], face[65])) / 3.0f;
  const bool fill_cavity = gap < kClosedMouthGap;

  for (const glm::vec2& p : points) out.mesh.points.push_back({p, p, p});
  const float cavity_y = float(height) + 0.5f * kCavityRows;
  for (const auto& t : triangles) {
    const glm::vec2 centroid = (layout[t[0]] + layout[t[1]] + layout[t[2]]) / 3.0f;
    const bool mouth = t[0] >= 60 && t[0] < 68 && t[1] >= 60 && t[1] < 68 && t[2] >= 60 && t[2] < 68;
    if (!(fill_cavity && mouth && inside(inner_lips, centroid))) {
      out.mesh.triangles.push_back(t);
      continue;
    }
    // Cavity: its own copies of the corners, reading the dark strip under the photo.
    std::array<uint32_t, 3> copy;
    for (int k = 0; k < 3; ++k) {
      copy[size_t(k)] = uint32_t(out.mesh.points.size());
      const glm::vec2 p = points[t[size_t(k)]];
      out.mesh.points.push_back({glm::vec2(p.x, cavity_y), p, p});
      out.landmark_of.push_back(int(t[size_t(k)]));
      out.head_point.push_back(out.head_point[t[size_t(k)]] - glm::vec3(0.0f, 0.0f, kCavityDepth));
      out.follows.push_back(1.0f);
    }
    out.mesh.triangles.push_back(copy);
  }
  return out;
}

glm::u8vec4 cavity_colour(const Image& photo, const FaceLandmarks& p) {
  glm::vec3 sum{0};
  int n = 0;
  for (int i = 48; i <= 59; ++i) {
    const glm::vec2 q = 0.5f * (p[size_t(i)] + p[size_t(60 + (i - 48) * 8 / 12)]);
    const int x = std::clamp(int(q.x), 0, photo.width - 1), y = std::clamp(int(q.y), 0, photo.height - 1);
    const uint8_t* c = &photo.pixels[(size_t(y) * size_t(photo.width) + size_t(x)) * 4];
    sum += glm::vec3(c[0], c[1], c[2]);
    ++n;
  }
  const glm::vec3 c = 0.3f * sum / float(n);
  return {uint8_t(c.r), uint8_t(c.g), uint8_t(c.b), 255};
}

}  // namespace inkwire
