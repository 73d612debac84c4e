#pragma once
// How a cell's control points are chosen where every candidate is already right (mesh products'
// exact points, a recovered shape's): the outline first, since the silhouette is where a warp
// shows its errors (a ghost of the edge wherever the samples disagree), then the rest, each group
// spread by farthest-point sampling from what is already chosen.
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

namespace inkwire {

// Indices into the candidates, in the order chosen: up to `outline_count` of those `on_outline`,
// then any, up to `count` in all. `layout` is where each candidate sits in the warp's
// triangulation; the first pick is the one farthest from their centroid, and the choosing stops
// early when every candidate left lies within half a pixel of a chosen one.
std::vector<size_t> spread_points(const std::vector<glm::vec2>& layout, const std::vector<bool>& on_outline, size_t outline_count, size_t count);

}  // namespace inkwire
