#include "common/tween/view_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace inkwire {

std::vector<glm::vec3> ring_directions(int count, float elevation_degrees) {
  std::vector<glm::vec3> out;
  const float el = glm::radians(elevation_degrees);
  for (int i = 0; i < count; ++i) {
    const float az = glm::radians(360.0f * float(i) / float(count));
    out.push_back({std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)});
  }
  return out;
}

std::vector<std::vector<uint16_t>> ring_cells(int count) {
  std::vector<std::vector<uint16_t>> cells;
  for (int i = 0; i < count; ++i) cells.push_back({uint16_t(i), uint16_t((i + 1) % count)});
  return cells;
}

ViewSphere geodesic_sphere(int subdivisions) {
  const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
  ViewSphere s;
  for (glm::vec3 v : {glm::vec3(-1, g, 0), glm::vec3(1, g, 0), glm::vec3(-1, -g, 0), glm::vec3(1, -g, 0),
                      glm::vec3(0, -1, g), glm::vec3(0, 1, g), glm::vec3(0, -1, -g), glm::vec3(0, 1, -g),
                      glm::vec3(g, 0, -1), glm::vec3(g, 0, 1), glm::vec3(-g, 0, -1), glm::vec3(-g, 0, 1)})
    s.directions.push_back(glm::normalize(v));
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<std::array<int, 3>> tris;
  for (const auto& f : faces) tris.push_back({f[0], f[1], f[2]});
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoints.find(key); it != midpoints.end()) return it->second;
      s.directions.push_back(glm::normalize(s.directions[a] + s.directions[b]));
      return midpoints[key] = int(s.directions.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : tris) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris = std::move(next);
  }
  for (const auto& t : tris) s.triangles.push_back({uint16_t(t[0]), uint16_t(t[1]), uint16_t(t[2])});
  return s;
}

Camera sample_camera(const Bounds& bounds, const glm::vec3& direction, float distance_diagonals) {
  const float diagonal = std::max(bounds.diagonal(), 1e-6f);
  const float distance = distance_diagonals * diagonal;
  const glm::vec3 d = glm::normalize(direction);
  Camera c;
  c.target = bounds.centre();
  c.position = c.target + distance * d;
  c.up = std::abs(d.y) > 0.999f ? glm::vec3(0.0f, 0.0f, d.y > 0 ? -1.0f : 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  c.near_plane = std::max(distance - diagonal, distance * 0.02f);
  c.far_plane = distance + diagonal;
  return c;
}

glm::vec3 halfway_direction(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 h = glm::normalize(a) + glm::normalize(b);
  const float n = glm::length(h);
  if (n > 1e-6f) return h / n;
  // Opposite directions: any perpendicular is halfway; take one reproducibly.
  const glm::vec3 axis = std::abs(a.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  return glm::normalize(glm::cross(a, axis));
}

namespace {

constexpr float kInside = 1e-3f;  // radians past a pair's end, or barycentric weight below 0, still inside

float angle_between(const glm::vec3& a, const glm::vec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

CellLocation locate_view(const TweenData& data, const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  CellLocation best;
  float best_miss = 1e9f;  // how far outside its cell the view is (0 = inside)
  for (size_t i = 0; i < data.cells.size(); ++i) {
    const TweenCell& cell = data.cells[i];
    if (cell.is_pair()) {
      const glm::vec3 a = glm::normalize(data.directions[cell.samples[0]]);
      const glm::vec3 b = glm::normalize(data.directions[cell.samples[1]]);
      glm::vec3 n = glm::cross(a, b);
      if (glm::length(n) < 1e-6f) continue;
      n = glm::normalize(n);
      glm::vec3 in_plane = d - glm::dot(d, n) * n;
      if (glm::length(in_plane) < 1e-6f) continue;
      in_plane = glm::normalize(in_plane);
      const float total = angle_between(a, b);
      const float theta = std::atan2(glm::dot(glm::cross(a, in_plane), n), glm::dot(a, in_plane));
      const float outside = std::max({0.0f, -theta, theta - total});
      const float miss = outside + std::abs(glm::dot(d, n)) * 1e-3f;  // prefer the ring the view is nearest
      if (miss < best_miss) {
        best_miss = miss;
        best.inside = outside <= kInside;
        best.cell = int(i);
        best.t = std::clamp(theta / total, 0.0f, 1.0f);
        best.weights = {1.0f - best.t, best.t, 0.0f};
      }
    } else {
      const glm::mat3 m(glm::normalize(data.directions[cell.samples[0]]), glm::normalize(data.directions[cell.samples[1]]),
                        glm::normalize(data.directions[cell.samples[2]]));
      if (std::abs(glm::determinant(m)) < 1e-9f) continue;
      glm::vec3 w = glm::inverse(m) * d;
      const float sum = w.x + w.y + w.z;
      if (sum <= 0.0f) continue;  // the ray leaves through the other side of the sphere
      w /= sum;
      const float miss = std::max({0.0f, -w.x, -w.y, -w.z});
      if (miss < best_miss) {
        best_miss = miss;
        best.inside = miss <= kInside;
        best.cell = int(i);
        w = glm::max(w, glm::vec3(0.0f));
        w /= (w.x + w.y + w.z);
        best.weights = {w.x, w.y, w.z};
        best.t = 0.0f;
      }
    }
  }
  return best;
}

double nearness(const glm::vec3& sample, const glm::vec3& direction) {
  const double x = sample.x, y = sample.y, z = sample.z;
  return (x * double(direction.x) + y * double(direction.y) + z * double(direction.z)) / std::sqrt(x * x + y * y + z * z);
}

int nearest_sample(const std::vector<glm::vec3>& directions, const glm::vec3& direction, const std::function<bool(int)>& usable) {
  int best = -1;
  double best_nearness = 0.0;
  for (size_t i = 0; i < directions.size(); ++i) {
    if (usable && !usable(int(i))) continue;
    const double n = nearness(directions[i], direction);
    if (best < 0 || n > best_nearness) best = int(i), best_nearness = n;
  }
  return best;
}

std::vector<int> view_samples(const TweenData& data, const glm::vec3& direction) {
  std::vector<int> out;
  const CellLocation at = locate_view(data, direction);
  if (at.cell >= 0 && at.inside)
    for (uint16_t s : data.cells[size_t(at.cell)].samples) out.push_back(s);
  const int nearest = nearest_sample(data.directions, direction);
  if (nearest >= 0 && std::find(out.begin(), out.end(), nearest) == out.end()) out.push_back(nearest);
  return out;
}

}  // namespace inkwire
