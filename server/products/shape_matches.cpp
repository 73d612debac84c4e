#include "server/products/shape_matches.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "server/products/depth_refinement.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire {
namespace {

// One direction of shape_matches: `from`'s pixels into `to`.
void follow_shape(const PhotoShape& shape, size_t from, size_t to, cv::Mat& flow, cv::Mat& reliable) {
  const TurntableCamera& c = shape.camera;
  flow = cv::Mat(c.height, c.width, CV_32FC2, cv::Scalar(0, 0));
  reliable = cv::Mat(c.height, c.width, CV_8U, cv::Scalar(0));
  const std::vector<float>& depth = shape.depth[from];
  const std::vector<float>& seen = shape.depth[to];
  // A point is seen by the other photo when that photo's nearest surface there is within this of it.
  const float near = 2.0f * shape.hull.voxel;
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const float z = depth[size_t(y * c.width + x)];
      if (z <= 0) continue;
      const glm::vec2 pixel(float(x) + 0.5f, float(y) + 0.5f);
      const glm::vec3 in_to = seen_from(c, shape.views[from], pixel, z, shape.views[to]);
      if (in_to.z <= 1e-3f) continue;
      const glm::vec2 there = to_pixel(c, in_to);
      const int tx = int(std::floor(there.x)), ty = int(std::floor(there.y));
      if (tx < 0 || ty < 0 || tx >= c.width || ty >= c.height) continue;
      const float other = seen[size_t(ty * c.width + tx)];
      flow.at<cv::Vec2f>(y, x) = cv::Vec2f(there.x - pixel.x, there.y - pixel.y);
      if (other > 0 && std::abs(other - in_to.z) <= near) reliable.at<uint8_t>(y, x) = 255;
    }
}

// How far `to` warped onto `from` by `flow` disagrees with it at each pixel (depth_refinement.hpp).
cv::Mat disagreement(const cv::Mat& from, const cv::Mat& to, const cv::Mat& flow) {
  cv::Mat map(flow.size(), CV_32FC2);
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x) {
      const cv::Vec2f f = flow.at<cv::Vec2f>(y, x);
      map.at<cv::Vec2f>(y, x) = cv::Vec2f(float(x) + f[0], float(y) + f[1]);
    }
  return warp_disagreement(from, to, map);
}

// One direction of merged_matches; returns how many of the kept pixels came from the shape.
size_t merge(const cv::Mat& from, const cv::Mat& to, const cv::Mat& matched, const cv::Mat& matched_ok, const cv::Mat& shaped,
             const cv::Mat& shaped_ok, cv::Mat& flow, cv::Mat& reliable, size_t& kept) {
  const cv::Mat matched_error = disagreement(from, to, matched), shaped_error = disagreement(from, to, shaped);
  flow = matched.clone();
  reliable = matched_ok.clone();
  size_t taken = 0;
  kept = 0;
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x) {
      const bool m = matched_ok.at<uint8_t>(y, x), s = shaped_ok.at<uint8_t>(y, x);
      if (s && (!m || shaped_error.at<float>(y, x) < matched_error.at<float>(y, x))) {
        flow.at<cv::Vec2f>(y, x) = shaped.at<cv::Vec2f>(y, x);
        reliable.at<uint8_t>(y, x) = 255;
        ++taken;
      }
      kept += reliable.at<uint8_t>(y, x) != 0;
    }
  return taken;
}

}  // namespace

DenseMatches shape_matches(const PhotoShape& shape, size_t a, size_t b) {
  DenseMatches m;
  follow_shape(shape, a, b, m.forward, m.reliable);
  follow_shape(shape, b, a, m.backward, m.reliable_backward);
  return m;
}

MergedMatches merged_matches(const DenseMatches& matched, const DenseMatches& shape, const Image& a, const Image& b) {
  const cv::Mat grey_a = grey_of(a), grey_b = grey_of(b);  // 0..1
  MergedMatches out;
  size_t kept = 0, kept_backward = 0;
  const size_t taken = merge(grey_a, grey_b, matched.forward, matched.reliable, shape.forward, shape.reliable, out.matches.forward,
                             out.matches.reliable, kept);
  merge(grey_b, grey_a, matched.backward, matched.reliable_backward, shape.backward, shape.reliable_backward, out.matches.backward,
        out.matches.reliable_backward, kept_backward);
  out.from_shape = kept ? double(taken) / double(kept) : 0;
  return out;
}

glm::vec2 arc_bulge(const PhotoShape& shape, size_t a, size_t b, glm::vec2 source) {
  const TurntableCamera& c = shape.camera;
  const PhotoView& from = shape.views[a];
  const PhotoView& to = shape.views[b];
  const int x = int(std::floor(source.x)), y = int(std::floor(source.y));
  if (from.row != to.row || x < 0 || y < 0 || x >= c.width || y >= c.height) return glm::vec2(0.0f);
  const float z = shape.depth[a][size_t(y * c.width + x)];
  if (z <= 0) return glm::vec2(0.0f);
  const float turn = std::remainder(to.azimuth_deg - from.azimuth_deg, 360.0f);
  const PhotoView halfway{.azimuth_deg = from.azimuth_deg + 0.5f * turn, .row = from.row};
  const glm::vec3 in_b = seen_from(c, from, source, z, to), in_halfway = seen_from(c, from, source, z, halfway);
  if (in_b.z <= 1e-3f || in_halfway.z <= 1e-3f) return glm::vec2(0.0f);
  return to_pixel(c, in_halfway) - 0.5f * (source + to_pixel(c, in_b));
}

}  // namespace inkwire
