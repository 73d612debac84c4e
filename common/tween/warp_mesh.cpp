#include "common/tween/warp_mesh.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace inkwire {
namespace {

struct Circle {
  double x, y, r2;
};

// Written as client/web/common/warp_mesh.js writes it, operation for operation, so both round alike.
Circle circumcircle(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  const double x = ((a.x * a.x + a.y * a.y) * (b.y - c.y) + (b.x * b.x + b.y * b.y) * (c.y - a.y) + (c.x * c.x + c.y * c.y) * (a.y - b.y)) / d;
  const double y = ((a.x * a.x + a.y * a.y) * (c.x - b.x) + (b.x * b.x + b.y * b.y) * (a.x - c.x) + (c.x * c.x + c.y * c.y) * (b.x - a.x)) / d;
  return {x, y, (a.x - x) * (a.x - x) + (a.y - y) * (a.y - y)};
}

constexpr double kNearSquared = 0.125 * 0.125;

}  // namespace

std::vector<std::array<uint32_t, 3>> delaunay_triangles(std::span<const glm::dvec2> points) {
  if (points.size() < 3) return {};
  std::vector<uint32_t> kept;
  for (uint32_t i = 0; i < points.size(); ++i) {
    const bool near = std::any_of(kept.begin(), kept.end(), [&](uint32_t j) {
      const double dx = points[j].x - points[i].x, dy = points[j].y - points[i].y;
      return dx * dx + dy * dy < kNearSquared;
    });
    if (!near) kept.push_back(i);
  }
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (const uint32_t i : kept) {
    min_x = std::min(min_x, points[i].x), max_x = std::max(max_x, points[i].x);
    min_y = std::min(min_y, points[i].y), max_y = std::max(max_y, points[i].y);
  }
  // Bowyer-Watson from a triangle far round them all, whose corners are left out at the end.
  const double span = std::max({max_x - min_x, max_y - min_y, 1.0}) * 20, cx = (min_x + max_x) / 2, cy = (min_y + max_y) / 2;
  std::vector<glm::dvec2> all(points.begin(), points.end());
  const auto corner = uint32_t(all.size());
  all.insert(all.end(), {{cx - span, cy - span}, {cx + span, cy - span}, {cx, cy + span}});
  struct Triangle {
    std::array<uint32_t, 3> v;
    Circle c;
  };
  const auto make = [&](uint32_t a, uint32_t b, uint32_t c) { return Triangle{{a, b, c}, circumcircle(all[a], all[b], all[c])}; };
  std::vector<Triangle> triangles{make(corner, corner + 1, corner + 2)}, good;
  // The hole's boundary, in the order its edges are first met: edges of exactly one bad triangle.
  std::vector<std::array<uint32_t, 2>> edges;
  std::vector<bool> boundary;
  std::unordered_map<uint64_t, size_t> edge_at;
  for (const uint32_t i : kept) {
    const glm::dvec2 p = all[i];
    good.clear(), edges.clear(), boundary.clear(), edge_at.clear();
    for (const Triangle& t : triangles) {
      const double dx = p.x - t.c.x, dy = p.y - t.c.y;
      if (!(dx * dx + dy * dy < t.c.r2 * (1 - 1e-12))) {
        good.push_back(t);
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        const uint32_t a = t.v[size_t(k)], b = t.v[size_t((k + 1) % 3)];
        const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
        const auto [at, first] = edge_at.emplace(key, edges.size());
        if (first) {
          edges.push_back({a, b});
          boundary.push_back(true);
        } else {
          boundary[at->second] = false;
        }
      }
    }
    triangles.swap(good);
    for (size_t e = 0; e < edges.size(); ++e)
      if (boundary[e]) triangles.push_back(make(edges[e][0], edges[e][1], i));
  }
  std::vector<std::array<uint32_t, 3>> out;
  for (const Triangle& t : triangles)
    if (t.v[0] < corner && t.v[1] < corner && t.v[2] < corner) out.push_back(t.v);
  return out;
}

std::vector<std::array<uint32_t, 3>> delaunay_triangles(std::span<const glm::vec2> points) {
  const std::vector<glm::dvec2> exact(points.begin(), points.end());
  return delaunay_triangles(exact);
}

std::vector<glm::vec2> border_points(int width, int height, int per_side) {
  std::vector<glm::vec2> out;
  const float w = float(width), h = float(height);
  for (int i = 0; i < per_side; ++i) {
    const float f = float(i) / float(per_side);
    out.push_back({f * w, 0.0f});
    out.push_back({w, f * h});
    out.push_back({(1.0f - f) * w, h});
    out.push_back({0.0f, (1.0f - f) * h});
  }
  return out;
}

WarpMesh build_warp_mesh(const TweenCell& cell, int width, int height) {
  WarpMesh mesh;
  mesh.points = cell.points;
  for (const glm::vec2& b : border_points(width, height)) mesh.points.push_back({b, b, b});
  // In double precision, as the browser lays them out.
  std::vector<glm::dvec2> layout;
  for (const ControlPoint& p : mesh.points)
    layout.push_back(cell.is_pair() ? (glm::dvec2(p[0]) + glm::dvec2(p[2])) / 2.0 : (glm::dvec2(p[0]) + glm::dvec2(p[1]) + glm::dvec2(p[2])) / 3.0);
  mesh.triangles = delaunay_triangles(layout);
  return mesh;
}

}  // namespace inkwire
