#include "client/render/sketch/perturb.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace inkwire {
namespace {

// Splits a->b in halves until pieces are no longer than the maximum (squared lengths, no
// square roots), appending the points after `a`.
void split(const glm::vec3& a, const glm::vec3& b, const glm::vec3& side_a, const glm::vec3& side_b, float max_segment2,
           std::vector<glm::vec3>& points, std::vector<glm::vec3>& sides) {
  const glm::vec3 d = b - a;
  if (glm::dot(d, d) > max_segment2) {
    const glm::vec3 mid = 0.5f * (a + b);
    glm::vec3 side = side_a + side_b;
    const float l = glm::length(side);
    side = l > 1e-12f ? side / l : side_a;
    split(a, mid, side_a, side, max_segment2, points, sides);
    split(mid, b, side, side_b, max_segment2, points, sides);
    return;
  }
  points.push_back(b);
  sides.push_back(side_b);
}

// One offset per point: ends first, then the midpoint of every index range, each moved by a
// random amount that halves with every level.
void displace(std::vector<float>& offset, size_t i, size_t j, float amplitude, StrokeRandom& random) {
  if (j <= i + 1) return;
  const size_t m = (i + j) / 2;
  offset[m] = 0.5f * (offset[i] + offset[j]) + random.uniform(-amplitude, amplitude);
  displace(offset, i, m, 0.5f * amplitude, random);
  displace(offset, m, j, 0.5f * amplitude, random);
}

}  // namespace

void perturb_stroke(const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& sides, const PerturbOptions& o,
                    StrokeRandom& random, std::vector<glm::vec3>& out) {
  if (points.size() < 2) return;
  float length = 0.0f;
  for (size_t i = 0; i + 1 < points.size(); ++i) length += glm::length(points[i + 1] - points[i]);
  const float amplitude = perturb_amplitude(length, o);
  const float q = 0.25f * amplitude;

  // Fine enough points to wobble: the stroke's own, split where pieces are too long.
  thread_local std::vector<glm::vec3> fine, fine_sides;
  thread_local std::vector<float> offset;
  fine.assign(1, points[0]);
  fine_sides.assign(1, sides[0]);
  const float max_segment = std::max(o.max_segment, 1e-6f);
  for (size_t i = 0; i + 1 < points.size(); ++i)
    split(points[i], points[i + 1], sides[i], sides[i + 1], max_segment * max_segment, fine, fine_sides);

  offset.assign(fine.size(), 0.0f);
  offset.front() = random.uniform(-q, q);
  offset.back() = random.uniform(-q, q);
  displace(offset, 0, fine.size() - 1, q, random);

  // Endpoint offsets along the stroke: overshoot or stop short by up to a quarter.
  const glm::vec3 start_dir = glm::normalize(fine[1] - fine[0] + glm::vec3(1e-12f));
  const glm::vec3 end_dir = glm::normalize(fine.back() - fine[fine.size() - 2] + glm::vec3(1e-12f));
  thread_local std::vector<glm::vec3> moved;
  moved.resize(fine.size());
  for (size_t i = 0; i < fine.size(); ++i) moved[i] = fine[i] + fine_sides[i] * offset[i];
  moved.front() -= start_dir * random.uniform(-q, q);
  moved.back() += end_dir * random.uniform(-q, q);

  // Moving points can stretch a piece past the maximum: split those straight, no new wobble.
  out.push_back(moved[0]);
  for (size_t i = 0; i + 1 < moved.size(); ++i) {
    const glm::vec3 a = moved[i], d = moved[i + 1] - a;
    const float pieces = std::ceil(std::sqrt(glm::dot(d, d) / (max_segment * max_segment)));
    for (float k = 1.0f; k < pieces; k += 1.0f) out.push_back(a + d * (k / pieces));
    out.push_back(moved[i + 1]);
  }
}

void perturb_edge(const glm::vec3& a, const glm::vec3& b, const glm::vec3& side, const PerturbOptions& o,
                  StrokeRandom& random, std::vector<glm::vec3>& out) {
  perturb_stroke({a, b}, {side, side}, o, random, out);
}

}  // namespace inkwire
