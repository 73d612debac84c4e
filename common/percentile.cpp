#include "common/percentile.hpp"

#include <opencv2/core.hpp>

namespace inkwire {

std::optional<float> masked_percentile(const cv::Mat& values, const cv::Mat& mask, double q) {
  if (values.type() != CV_32FC1) throw Error("a masked percentile reads one-channel float pixels");
  if (mask.type() != CV_8UC1 || mask.size() != values.size()) throw Error("a masked percentile's mask is not 8-bit of the pixels' size");
  std::vector<float> picked;
  picked.reserve(size_t(cv::countNonZero(mask)));
  for (int y = 0; y < values.rows; ++y) {
    const float* v = values.ptr<float>(y);
    const uint8_t* m = mask.ptr<uint8_t>(y);
    for (int x = 0; x < values.cols; ++x)
      if (m[x]) picked.push_back(v[x]);
  }
  return percentile_in_place(std::span<float>(picked), q);
}

}  // namespace inkwire
