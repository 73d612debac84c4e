#include "server/products/depth_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <opencv2/imgproc.hpp>

#include "server/tween/landmarks.hpp"

namespace inkwire {
namespace {

// How far photo `to` warped onto photo `from` disagrees with it at every pixel, when each pixel of
// `from` is taken to lie `behind` further along its ray than `depth` says.
cv::Mat disagreement_at(const std::vector<float>& depth, float behind, const TurntableCamera& camera, const PhotoView& from_view,
                        const PhotoView& to_view, const cv::Mat& from, const cv::Mat& to) {
  cv::Mat map(from.size(), CV_32FC2, cv::Scalar(-1, -1));
  for (int y = 0; y < from.rows; ++y)
    for (int x = 0; x < from.cols; ++x) {
      const float z = depth[size_t(y * from.cols + x)];
      if (z <= 0) continue;
      const glm::vec3 in_to = seen_from(camera, from_view, glm::vec2(float(x) + 0.5f, float(y) + 0.5f), z + behind, to_view);
      if (in_to.z <= 1e-3f) continue;
      const glm::vec2 there = to_pixel(camera, in_to);
      map.at<cv::Vec2f>(y, x) = cv::Vec2f(there.x - 0.5f, there.y - 0.5f);
    }
  return warp_disagreement(from, to, map);
}

}  // namespace

cv::Mat warp_disagreement(const cv::Mat& from, const cv::Mat& to, const cv::Mat& map) {
  cv::Mat warped, error;
  cv::remap(to, warped, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(-10));
  cv::absdiff(from, warped, error);
  cv::blur(error, error, cv::Size(5, 5));
  return error;
}

void refine_depth(std::vector<std::vector<float>>& depth, const TurntableCamera& camera, const std::vector<PhotoView>& views,
                  const std::vector<const Image*>& photos, int columns, float cell) {
  std::vector<cv::Mat> grey;
  for (const Image* photo : photos) grey.push_back(grey_of(*photo));
  const std::vector<std::vector<float>> hull = depth;  // every photo refined against the others' hull depths as carved
  const auto refine = [&](size_t v) {
    const size_t row = v / size_t(columns), column = v % size_t(columns);
    const size_t neighbours[2] = {row * size_t(columns) + (column + size_t(columns) - 1) % size_t(columns),
                                  row * size_t(columns) + (column + 1) % size_t(columns)};
    cv::Mat best_cost, at_hull;
    cv::Mat best_behind(grey[v].size(), CV_32F, cv::Scalar(0));
    for (float step = -1.0f; step <= kSweepCells; step += kSweepStep) {
      cv::Mat cost;
      for (const size_t n : neighbours) {
        const cv::Mat c = disagreement_at(hull[v], step * cell, camera, views[v], views[n], grey[v], grey[n]);
        cost = cost.empty() ? c : cv::min(cost, c);
      }
      if (step == 0.0f) at_hull = cost.clone();
      if (best_cost.empty()) {
        best_cost = cost.clone();
        best_behind.setTo(step * cell);
        continue;
      }
      const cv::Mat better = cost < best_cost;
      cost.copyTo(best_cost, better);
      best_behind.setTo(step * cell, better);
    }
    for (int y = 0; y < grey[v].rows; ++y)
      for (int x = 0; x < grey[v].cols; ++x) {
        float& z = depth[v][size_t(y * grey[v].cols + x)];
        if (z > 0 && best_cost.at<float>(y, x) < kClearlyAgrees * at_hull.at<float>(y, x)) z += best_behind.at<float>(y, x);
      }
  };
  const size_t workers = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 8);
  std::vector<std::thread> threads;
  for (size_t w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (size_t v = w; v < depth.size(); v += workers) refine(v);
    });
  for (std::thread& t : threads) t.join();
}

}  // namespace inkwire
