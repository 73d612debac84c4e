#pragma once
// Where samples are taken from (SPEC T1) and which samples a view is synthesised from (T4):
// rings on the equator, geodesic spheres, and locating a view direction among the cells.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "common/camera.hpp"
#include "common/tween/tween_data.hpp"

namespace inkwire {

// `count` directions around the +Y axis at `elevation_degrees`, azimuth 0 (toward +Z) first,
// increasing the way orbit_camera() turns.
std::vector<glm::vec3> ring_directions(int count, float elevation_degrees = 0.0f);
// Consecutive pairs of a closed ring of `count` samples: (0,1), (1,2), ..., (count-1, 0).
std::vector<std::vector<uint16_t>> ring_cells(int count);

struct ViewSphere {
  std::vector<glm::vec3> directions;
  std::vector<std::vector<uint16_t>> triangles;  // spherical triangles, counter-clockwise seen from outside
};
// The icosahedron, each face split into 4 `subdivisions` times (0: 12 samples, 1: 42, 2: 162).
ViewSphere geodesic_sphere(int subdivisions);

// The camera a sample along `direction` is taken with: on the ray from the centre of `bounds`,
// `distance_diagonals` bounding-box diagonals away, looking at the centre, +Y up (+Z near the
// poles), the default 45-degree field of view.
Camera sample_camera(const Bounds& bounds, const glm::vec3& direction, float distance_diagonals);

// Direction halfway along the great circle from a to b.
glm::vec3 halfway_direction(const glm::vec3& a, const glm::vec3& b);

// Where a view direction falls among the cells: the cell, and the weight of each of its samples
// (summing to 1). For a pair, weights are (1 - t, t) with t the angle fraction from a to b of
// the view projected onto their great circle; for a triangle, the barycentric coordinates of
// the view ray through the triangle's plane.
struct CellLocation {
  int cell = -1;  // -1 when no cell holds the direction
  float t = 0.0f;  // pairs: 0 at the first sample, 1 at the second
  std::array<float, 3> weights{1.0f, 0.0f, 0.0f};
  bool inside = false;  // the view lies within the cell (not past an open ring's end, above the top row, ...)
};
CellLocation locate_view(const TweenData& data, const glm::vec3& direction);

// How near a sample's direction lies to a view direction: the cosine of their angle times the
// view direction's length (the same for every sample, so it orders them as the cosine does).
// In double, step for step as the browser's client/web/common/view_sphere.js nearness(), so both
// pick the same sample on a tie (tests/golden/warp-vectors.json).
double nearness(const glm::vec3& sample, const glm::vec3& direction);
// The sample nearest `direction` among those `usable` allows (every one when empty), the first on
// a tie; -1 when none is.
int nearest_sample(const std::vector<glm::vec3>& directions, const glm::vec3& direction, const std::function<bool(int)>& usable = {});
// The samples a view from `direction` is drawn from once they are there: its cell's when it lies
// inside one, and the nearest.
std::vector<int> view_samples(const TweenData& data, const glm::vec3& direction);

}  // namespace inkwire
