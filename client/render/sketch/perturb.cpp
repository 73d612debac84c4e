#include "client/render/sketch/perturb.hpp"

#include <glm/geometric.hpp>

namespace inkwire {
namespace {

void subdivide(const glm::vec3& a, const glm::vec3& b, float amplitude, const glm::vec3& side, float max_segment2,
               StrokeRandom& random, std::vector<glm::vec3>& out) {
  const glm::vec3 d = b - a;
  if (glm::dot(d, d) <= max_segment2) {  // squared lengths: no square root per test
    out.push_back(b);
    return;
  }
  const glm::vec3 mid = 0.5f * (a + b) + side * random.uniform(-amplitude, amplitude);
  subdivide(a, mid, 0.5f * amplitude, side, max_segment2, random, out);
  subdivide(mid, b, 0.5f * amplitude, side, max_segment2, random, out);
}

}  // namespace

void perturb_edge(const glm::vec3& a, const glm::vec3& b, const glm::vec3& side, const PerturbOptions& o,
                  StrokeRandom& random, std::vector<glm::vec3>& out) {
  const glm::vec3 d = b - a;
  const float length = glm::length(d);
  const float amplitude = perturb_amplitude(length, o);
  const glm::vec3 along = length > 0.0f ? d / length : glm::vec3(0.0f);
  // Endpoints: a quarter of the amplitude along (overshoot or stop short) and across.
  const float q = 0.25f * amplitude;
  const glm::vec3 start = a + along * random.uniform(-q, q) + side * random.uniform(-q, q);
  const glm::vec3 end = b + along * random.uniform(-q, q) + side * random.uniform(-q, q);
  out.push_back(start);
  const float max_segment = std::max(o.max_segment, 1e-6f);
  subdivide(start, end, q, side, max_segment * max_segment, random, out);
}

}  // namespace inkwire
