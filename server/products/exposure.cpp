#include "server/products/exposure.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/core.hpp>

namespace inkwire {

PairExposure pair_exposure(const DenseMatches& matches, const Image& a, const Image& b, int index_a, int index_b) {
  PairExposure out;
  out.a = index_a, out.b = index_b;
  std::vector<float> ratios[3];
  // Every other pixel both ways is plenty; clipped and near-black pixels say nothing of a gain.
  for (int y = 0; y < a.height; y += 2)
    for (int x = 0; x < a.width; x += 2) {
      if (!matches.reliable.at<uint8_t>(y, x)) continue;
      const cv::Point2f q = flow_at(matches.forward, {float(x), float(y)});
      const int qx = std::clamp(int(std::lround(q.x)), 0, b.width - 1), qy = std::clamp(int(std::lround(q.y)), 0, b.height - 1);
      const uint8_t* pa = a.at(x, y);
      const uint8_t* pb = b.at(qx, qy);
      bool usable = true;
      for (int c = 0; c < 3; ++c) usable = usable && pa[c] >= 16 && pa[c] <= 245 && pb[c] >= 16 && pb[c] <= 245;
      if (!usable) continue;
      for (int c = 0; c < 3; ++c) ratios[c].push_back(std::log(float(pb[c]) / float(pa[c])));
    }
  out.count = int(ratios[0].size());
  if (out.count < 200) {
    out.count = 0;
    return out;
  }
  for (int c = 0; c < 3; ++c) {
    auto mid = ratios[c].begin() + long(ratios[c].size() / 2);
    std::nth_element(ratios[c].begin(), mid, ratios[c].end());
    out.log_ratio[c] = *mid;
  }
  return out;
}

std::vector<glm::vec3> exposure_gains(const std::vector<PairExposure>& pairs, int photos, bool closed) {
  std::vector<glm::vec3> gains(size_t(photos), glm::vec3(1.0f));
  if (photos < 2) return gains;
  // Unknown log brightness l_i per photo: l_b - l_a = log_ratio for every pair, sum of l = 0.
  // (At least as many rows as unknowns, zero rows where pairs are missing: SVD solves any such.)
  const int rows = std::max(int(pairs.size()) + 1, photos);
  cv::Mat system(rows, photos, CV_64F, cv::Scalar(0)), right(rows, 3, CV_64F, cv::Scalar(0));
  int row = 0;
  for (const PairExposure& p : pairs) {
    if (p.count == 0) continue;
    system.at<double>(row, p.b) += 1.0;
    system.at<double>(row, p.a) -= 1.0;
    for (int c = 0; c < 3; ++c) right.at<double>(row, c) = p.log_ratio[c];
    ++row;
  }
  if (row == 0) return gains;
  for (int i = 0; i < photos; ++i) system.at<double>(row, i) = 1.0;
  cv::Mat levels;
  cv::solve(system, right, levels, cv::DECOMP_SVD);
  for (int i = 0; i < photos; ++i)
    for (int c = 0; c < 3; ++c) {
      std::vector<double> around;
      for (int k : {-2, -1, 1, 2}) {
        const int j = closed ? (i + k + photos) % photos : i + k;
        if (j >= 0 && j < photos && j != i) around.push_back(levels.at<double>(j, c));
      }
      if (around.empty()) continue;
      std::sort(around.begin(), around.end());
      const double trend = around.size() % 2 ? around[around.size() / 2] : 0.5 * (around[around.size() / 2 - 1] + around[around.size() / 2]);
      gains[size_t(i)][c] = float(std::exp(trend - levels.at<double>(i, c)));
    }
  return gains;
}

void apply_gain(Image& photo, const glm::vec3& gain) {
  for (size_t i = 0; i < photo.pixels.size(); i += 4)
    if (photo.pixels[i + 3] != 0)  // where a matte is 0 the floor layer is already on white
      for (int c = 0; c < 3; ++c) photo.pixels[i + size_t(c)] = uint8_t(std::clamp(std::lround(float(photo.pixels[i + size_t(c)]) * gain[c]), 0L, 255L));
}

}  // namespace inkwire
