// The one percentile (common/percentile.hpp): the element at rank floor(q * n), the upper median
// at n / 2, nothing for no values, and its masked form over a picture.
#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "common/percentile.hpp"

namespace inkwire {
namespace {

TEST(PercentileTest, TheMedianOfAnOddCountIsTheMiddleOne) {
  EXPECT_EQ(median(std::vector<int>{9, 1, 5, 3, 7}), 5);
  EXPECT_EQ(median(std::vector<float>{2.5f}), 2.5f);
}

TEST(PercentileTest, TheMedianOfAnEvenCountIsTheUpperOfTheTwoMiddleOnes) {
  EXPECT_EQ(median(std::vector<int>{4, 1, 3, 2}), 3) << "rank n / 2, an element of the input, not 2.5";
  EXPECT_EQ(median(std::vector<float>{1.0f, 0.0f}), 1.0f);
}

TEST(PercentileTest, ZeroIsTheSmallestAndOneTheLargest) {
  const std::vector<double> v = {3, -2, 8, 0.5, 8, 1};
  EXPECT_EQ(percentile(v, 0.0), -2);
  EXPECT_EQ(percentile(v, 1.0), 8);
  EXPECT_EQ(percentile(std::vector<int>{7}, 1.0), 7);
}

TEST(PercentileTest, ARankIsTheFloorOfQTimesTheCount) {
  std::vector<int> v(20);
  for (int i = 0; i < 20; ++i) v[size_t(i)] = 19 - i;  // 19 .. 0
  EXPECT_EQ(percentile(v, 0.9), 18) << "rank 20 * 9 / 10";
  EXPECT_EQ(percentile(v, 0.049), 0);
  EXPECT_EQ(percentile(v, 0.05), 1);
  for (size_t n = 1; n < 200; ++n) {
    std::vector<int> ranks(n);
    for (size_t i = 0; i < n; ++i) ranks[i] = int(n - 1 - i);
    EXPECT_EQ(percentile(ranks, 0.9), int(n * 9 / 10)) << n << " values: as integer arithmetic picks it";
    EXPECT_EQ(median(ranks), int(n / 2)) << n << " values";
  }
}

TEST(PercentileTest, OnACopyTheValuesKeepTheirOrderAndInPlaceTheyAreReordered) {
  const std::vector<int> v = {5, 4, 3, 2, 1};
  EXPECT_EQ(percentile(v, 0.5), 3);
  EXPECT_EQ(v, (std::vector<int>{5, 4, 3, 2, 1}));
  std::vector<int> w = v;
  EXPECT_EQ(median_in_place(std::span<int>(w)), 3);
  EXPECT_EQ(w[2], 3) << "as nth_element leaves it";
}

TEST(PercentileTest, NoValuesHaveNoPercentile) {
  EXPECT_EQ(median(std::vector<float>{}), std::nullopt);
  EXPECT_EQ(percentile(std::vector<int>{}, 1.0), std::nullopt);
}

TEST(PercentileTest, AShareOutsideZeroToOneIsRefused) {
  EXPECT_THROW(percentile(std::vector<int>{1, 2}, 1.5), Error);
  EXPECT_THROW(percentile(std::vector<int>{1, 2}, -0.1), Error);
  EXPECT_THROW(percentile(std::vector<int>{1, 2}, std::nan("")), Error);
  EXPECT_THROW(percentile(std::vector<int>{}, 2.0), Error) << "with no values as well";
}

TEST(PercentileTest, AMaskedPercentileReadsOnlyThePixelsTheMaskHolds) {
  cv::Mat values(3, 4, CV_32F), mask(3, 4, CV_8U, cv::Scalar(0));
  for (int i = 0; i < 12; ++i) values.at<float>(i / 4, i % 4) = float(100 - i);
  // Held: 99, 96, 93, 90, 89 (row 0's second, row 1's first and last, row 2's last two).
  mask.at<uint8_t>(0, 1) = 255, mask.at<uint8_t>(1, 0) = 1, mask.at<uint8_t>(1, 3) = 7, mask.at<uint8_t>(2, 2) = 255, mask.at<uint8_t>(2, 3) = 255;
  EXPECT_EQ(masked_median(values, mask), 93.0f);
  EXPECT_EQ(masked_percentile(values, mask, 0.0), 89.0f);
  EXPECT_EQ(masked_percentile(values, mask, 1.0), 99.0f);
  EXPECT_EQ(masked_percentile(values, mask, 0.9), 99.0f) << "rank 5 * 9 / 10 = 4";
  EXPECT_EQ(masked_median(values, cv::Mat(3, 4, CV_8U, cv::Scalar(0))), std::nullopt) << "a mask holding nothing";
  // A region of interest (rows not contiguous) reads as its own picture.
  const cv::Rect corner(1, 1, 3, 2);  // holds 93, 90, 89
  EXPECT_EQ(masked_percentile(values(corner), mask(corner), 1.0), 93.0f);
  EXPECT_EQ(masked_percentile(values(corner), mask(corner), 0.0), 89.0f);
}

TEST(PercentileTest, AMaskedPercentileRefusesOtherTypesAndSizes) {
  const cv::Mat values(2, 2, CV_32F, cv::Scalar(1)), mask(2, 2, CV_8U, cv::Scalar(1));
  EXPECT_THROW(masked_median(cv::Mat(2, 2, CV_8U, cv::Scalar(1)), mask), Error);
  EXPECT_THROW(masked_median(values, cv::Mat(2, 3, CV_8U, cv::Scalar(1))), Error);
  EXPECT_THROW(masked_median(values, cv::Mat(2, 2, CV_32F, cv::Scalar(1))), Error);
}

}  // namespace
}  // namespace inkwire
