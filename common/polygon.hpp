#pragma once
// Whether a point lies inside a polygon (its vertices in order, closed implicitly), by the
// even-odd rule: a ray to the right crosses the outline an odd number of times.
#include <span>

#include <glm/vec2.hpp>

namespace inkwire {

inline bool inside_polygon(std::span<const glm::vec2> polygon, glm::vec2 p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

}  // namespace inkwire
