#include "common/tween/point_spread.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace inkwire {

std::vector<size_t> spread_points(const std::vector<glm::vec2>& layout, const std::vector<bool>& on_outline, size_t outline_count, size_t count) {
  std::vector<size_t> chosen;
  if (layout.empty()) return chosen;
  glm::vec2 centroid(0.0f);
  for (const glm::vec2& l : layout) centroid += l;
  centroid /= float(layout.size());
  std::vector<float> distance(layout.size(), std::numeric_limits<float>::max());
  const auto spread = [&](size_t until, bool outline_only) {
    while (chosen.size() < until) {
      size_t next = layout.size();
      float best = -1.0f;
      for (size_t i = 0; i < layout.size(); ++i) {
        if (outline_only && !on_outline[i]) continue;
        const float d = chosen.empty() ? glm::length(layout[i] - centroid) : distance[i];
        if (d > best) best = d, next = i;
      }
      if (next == layout.size() || (!chosen.empty() && best < 0.5f)) return;
      chosen.push_back(next);
      for (size_t j = 0; j < layout.size(); ++j) distance[j] = std::min(distance[j], glm::length(layout[j] - layout[next]));
    }
  };
  spread(std::min(outline_count, count), true);
  spread(count, false);
  return chosen;
}

}  // namespace inkwire
