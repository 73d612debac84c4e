#pragma once
// One percentile for every caller: the element at rank floor(q * n) of n values (clamped to the
// last), found by std::nth_element. The median is the upper one, rank n / 2, an element of the
// input (never the mean of two), which is what the product's thresholds were tuned with. Empty
// input has no percentile: the answer is empty and each caller says what it does then. q outside
// 0..1 (or NaN) is a caller's bug and throws inkwire::Error.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/error.hpp"

namespace cv {
class Mat;
}

namespace inkwire {

// The rank percentile() picks among n > 0 values.
inline size_t percentile_rank(size_t n, double q) {
  if (!(q >= 0.0 && q <= 1.0)) throw Error("a percentile of " + std::to_string(q) + " is not in 0..1");
  return std::min(n - 1, size_t(q * double(n)));
}

// Reorders `values` (as nth_element does) and returns the q-th percentile; empty for no values.
template <typename T>
std::optional<T> percentile_in_place(std::span<T> values, double q) {
  if (values.empty()) {
    percentile_rank(1, q);  // a bad q is refused with or without values
    return std::nullopt;
  }
  const auto at = values.begin() + std::ptrdiff_t(percentile_rank(values.size(), q));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

// The same on a copy, leaving the caller's values in their order.
template <typename T>
std::optional<T> percentile(std::vector<T> values, double q) {
  return percentile_in_place(std::span<T>(values), q);
}

template <typename T>
std::optional<T> median_in_place(std::span<T> values) {
  return percentile_in_place(values, 0.5);
}

template <typename T>
std::optional<T> median(std::vector<T> values) {
  return percentile(std::move(values), 0.5);
}

// The q-th percentile of a one-channel float picture's pixels where `mask` (8-bit, same size) is
// not 0; empty where the mask holds none. Other types or sizes throw inkwire::Error.
std::optional<float> masked_percentile(const cv::Mat& values, const cv::Mat& mask, double q);

inline std::optional<float> masked_median(const cv::Mat& values, const cv::Mat& mask) { return masked_percentile(values, mask, 0.5); }

}  // namespace inkwire
