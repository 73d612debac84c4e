#include "common/tween/warp_mesh.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include <glm/common.hpp>
#include <opencv2/imgproc.hpp>

namespace inkwire {
namespace {
constexpr int kFirstRealVertex = 4;  // Subdiv2D's vertices 0..3 are a dummy and its outer triangle
}  // namespace

std::vector<std::array<uint32_t, 3>> delaunay_triangles(std::span<const glm::vec2> points) {
  if (points.size() < 3) return {};
  glm::vec2 lo = points[0], hi = points[0];
  for (const glm::vec2& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Subdiv2D wants every point strictly inside its rectangle.
  cv::Subdiv2D subdiv(cv::Rect(int(lo.x) - 2, int(lo.y) - 2, int(hi.x - lo.x) + 5, int(hi.y - lo.y) + 5));
  std::map<std::pair<float, float>, uint32_t> index_of;
  for (size_t i = 0; i < points.size(); ++i) {
    const cv::Point2f p(points[i].x, points[i].y);
    if (i > 0) {
      cv::Point2f nearest;
      const int vertex = subdiv.findNearest(p, &nearest);
      if (vertex >= kFirstRealVertex && cv::norm(nearest - p) < 0.125) continue;
    }
    subdiv.insert(p);
    index_of.emplace(std::pair{p.x, p.y}, uint32_t(i));
  }
  std::vector<cv::Vec6f> list;
  subdiv.getTriangleList(list);
  std::vector<std::array<uint32_t, 3>> triangles;
  for (const cv::Vec6f& t : list) {
    std::array<uint32_t, 3> tri{};
    bool known = true;
    for (int k = 0; k < 3 && known; ++k) {
      auto it = index_of.find({t[2 * k], t[2 * k + 1]});
      known = it != index_of.end();
      if (known) tri[k] = it->second;
    }
    if (known) triangles.push_back(tri);
  }
  return triangles;
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
  std::vector<glm::vec2> layout;
  for (const ControlPoint& p : mesh.points) layout.push_back(cell.is_pair() ? (p[0] + p[2]) * 0.5f : (p[0] + p[1] + p[2]) / 3.0f);
  mesh.triangles = delaunay_triangles(layout);
  return mesh;
}

}  // namespace inkwire
