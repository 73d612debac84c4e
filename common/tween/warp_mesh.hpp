#pragma once
// The triangulated control points a warp draws (SPEC T3): Delaunay triangles computed once per
// cell on the points' mean positions in the cell's samples (where folds are rarest), over the
// cell's points plus fixed points along the image border so the whole image is covered and its
// frame stays put. Clients (C++ and client/web/common/warp_mesh.js) triangulate alike.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/ext/vector_double2.hpp>

#include "common/tween/tween_data.hpp"

namespace inkwire {

struct WarpMesh {
  std::vector<ControlPoint> points;  // the cell's points, then the border points
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Delaunay triangles of `points` as index triples (Bowyer-Watson, in the browser too: the same
// steps in client/web/common/warp_mesh.js pick the same triangles where four points lie on one
// circle, as the border points do; tests/golden/warp-vectors.json pins it). Points closer than
// 1/8 pixel to an earlier one are left out of the triangles (they would fold).
std::vector<std::array<uint32_t, 3>> delaunay_triangles(std::span<const glm::dvec2> points);
std::vector<std::array<uint32_t, 3>> delaunay_triangles(std::span<const glm::vec2> points);

// Border points every `border_step` pixels or so (corners included), the same in every sample.
std::vector<glm::vec2> border_points(int width, int height, int per_side = 4);

// The cell's control points extended by the border, triangulated where a pair's point lies
// midway between its two samples' positions, or a triangle's at the centroid of its three. Not
// at a pair's halfway view: where a surface turns out of sight, its points meet the outline of
// what is in front there, and triangles laid out on a collapsed surface fold on either side.
WarpMesh build_warp_mesh(const TweenCell& cell, int width, int height);

}  // namespace inkwire
