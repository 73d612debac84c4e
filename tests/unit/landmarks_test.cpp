// Automatic landmarks (SPEC T7) on synthetic images: each candidate rule turns away what it
// should (border, spacing, weak structure, self-similar texture, repeated targets), and
// landmarks on a shifted image are found at the shift.
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/random.hpp"
#include "server/tween/landmarks.hpp"

using namespace inkwire;

namespace {

// Grey noise blobs: distinctive everywhere except where said otherwise.
cv::Mat blobs(int w, int h, uint64_t seed, int count = 60) {
  cv::Mat m(h, w, CV_32F, cv::Scalar(0.5));
  Random random(seed);
  for (int i = 0; i < count; ++i) {
    const cv::Point c(int(random.uniform(0.0f, float(w))), int(random.uniform(0.0f, float(h))));
    cv::circle(m, c, int(random.uniform(2.0f, 9.0f)), cv::Scalar(random.uniform(0.0f, 1.0f)), cv::FILLED);
    cv::rectangle(m, cv::Rect(int(random.uniform(0.0f, float(w))), int(random.uniform(0.0f, float(h))), 6, 4),
                  cv::Scalar(random.uniform(0.0f, 1.0f)), cv::FILLED);
  }
  cv::GaussianBlur(m, m, cv::Size(3, 3), 0.7);
  return m;
}

cv::Mat shifted(const cv::Mat& m, float dx, float dy) {
  cv::Mat out;
  const cv::Mat t = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy);
  cv::warpAffine(m, out, t, m.size(), cv::INTER_CUBIC, cv::BORDER_REFLECT);
  return out;
}

}  // namespace

TEST(LandmarksTest, ShiftedImageGivesTheShiftEverywhere) {
  const cv::Mat a = blobs(256, 256, 1);
  const cv::Mat b = shifted(a, 7.0f, 3.0f);
  LandmarkStats stats;
  const auto found = find_landmarks(a, b, LandmarkOptions{}, &stats);
  ASSERT_GE(found.size(), 40u) << "candidates " << stats.candidates;
  for (const Landmark& l : found) {
    EXPECT_NEAR(l.target.x - l.source.x, 7.0f, 0.3f);
    EXPECT_NEAR(l.target.y - l.source.y, 3.0f, 0.3f);
  }
}

TEST(LandmarksTest, Rule1KeepsAwayFromTheBorder) {
  const cv::Mat a = blobs(200, 160, 2, 120);
  LandmarkOptions o;
  o.count = 500;
  const auto found = find_landmarks(a, a, o);
  ASSERT_FALSE(found.empty());
  const int margin = o.window / 2 * 2 + 3;
  for (const Landmark& l : found) {
    EXPECT_GE(l.source.x, float(margin));
    EXPECT_GE(l.source.y, float(margin));
    EXPECT_LT(l.source.x, 200.0f - margin);
    EXPECT_LT(l.source.y, 160.0f - margin);
  }
  EXPECT_FALSE(far_from_border({3, 80}, {200, 160}, 10));
  EXPECT_TRUE(far_from_border({100, 80}, {200, 160}, 10));
}

TEST(LandmarksTest, Rule2SpacesThemOut) {
  const cv::Mat a = blobs(256, 256, 3, 200);
  LandmarkOptions o;
  o.count = 500;
  o.min_spacing = 14.0f;
  const auto found = find_landmarks(a, a, o);
  ASSERT_GT(found.size(), 20u);
  for (size_t i = 0; i < found.size(); ++i)
    for (size_t j = 0; j < i; ++j) EXPECT_GE(glm::length(found[i].source - found[j].source), 14.0f);
}

TEST(LandmarksTest, Rule3FindsNothingOnFlatOrSmoothImages) {
  cv::Mat gradient(128, 128, CV_32F);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) gradient.at<float>(y, x) = float(x + y) / 256.0f;
  // Structure relative to the strongest: add one strong blob so the smooth ramp is "weak".
  cv::circle(gradient, {64, 64}, 5, cv::Scalar(1.0), cv::FILLED);
  LandmarkStats stats;
  const auto found = find_landmarks(gradient, gradient, LandmarkOptions{}, &stats);
  for (const Landmark& l : found) EXPECT_LT(glm::length(l.source - glm::vec2(64, 64)), 9.0f) << "a landmark on the smooth ramp";
  EXPECT_GT(stats.weak, 0);
  // A lone straight edge has no structure across it (its smaller eigenvalue is ~0).
  cv::Mat edge(64, 64, CV_32F, cv::Scalar(0.0));
  edge(cv::Rect(32, 0, 32, 64)) = 1.0;
  const cv::Mat s = structure_strength(edge, 11);
  const cv::Mat corner_like = structure_strength(blobs(64, 64, 4), 11);
  double edge_max = 0, blob_max = 0;
  cv::minMaxLoc(s(cv::Rect(10, 10, 44, 44)), nullptr, &edge_max);
  cv::minMaxLoc(corner_like, nullptr, &blob_max);
  EXPECT_LT(edge_max, 0.05 * blob_max);
}

TEST(LandmarksTest, Rule4RejectsSelfSimilarTexture) {
  // Fine stripes: every patch matches itself shifted by one period.
  cv::Mat stripes(128, 128, CV_32F);
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) stripes.at<float>(y, x) = ((x / 3 + y / 3) % 2) ? 0.9f : 0.1f;
  EXPECT_GT(self_match(stripes, {64, 64}, 11), 0.85f);
  const cv::Mat b = blobs(128, 128, 5);
  // An isolated blob edge does not look like its neighbourhood.
  cv::Mat strength = structure_strength(b, 11);
  cv::Point best;
  cv::minMaxLoc(strength(cv::Rect(20, 20, 88, 88)), nullptr, nullptr, nullptr, &best);
  EXPECT_LT(self_match(b, best + cv::Point(20, 20), 11), 0.85f);
  LandmarkStats stats;
  EXPECT_TRUE(find_landmarks(stripes, stripes, LandmarkOptions{}, &stats).empty());
  EXPECT_GT(stats.not_distinctive, 0);
}

TEST(LandmarksTest, Rule5RejectsATargetWithTwoEqualMatches) {
  cv::Mat a(100, 160, CV_32F, cv::Scalar(0.5));
  cv::circle(a, {60, 50}, 4, cv::Scalar(1.0), cv::FILLED);
  cv::rectangle(a, cv::Rect(62, 48, 5, 3), cv::Scalar(0.0), cv::FILLED);
  // The target holds the same feature twice, 20 pixels apart, both within the search.
  cv::Mat b(100, 160, CV_32F, cv::Scalar(0.5));
  a(cv::Rect(50, 40, 20, 20)).copyTo(b(cv::Rect(45, 40, 20, 20)));
  a(cv::Rect(50, 40, 20, 20)).copyTo(b(cv::Rect(65, 40, 20, 20)));
  const PatchMatch m = match_patch(a, {60, 50}, b, {40, 12}, 11);
  EXPECT_GT(m.best, 0.95f);
  EXPECT_GT(m.runner_up, 0.95f);
  LandmarkStats stats;
  LandmarkOptions o;
  o.max_neighbour_disagreement = 0.0f;
  EXPECT_TRUE(find_landmarks(a, b, o, &stats).empty());
  EXPECT_GT(stats.not_unique, 0);
}

TEST(LandmarksTest, SubPixelShiftsAreResolved) {
  const cv::Mat a = blobs(160, 160, 6);
  const cv::Mat b = shifted(a, 2.4f, -1.7f);
  cv::Mat strength = structure_strength(a, 11);
  cv::Point best;
  cv::minMaxLoc(strength(cv::Rect(30, 30, 100, 100)), nullptr, nullptr, nullptr, &best);
  const cv::Point p = best + cv::Point(30, 30);
  const PatchMatch m = match_patch(a, p, b, {10, 10}, 11);
  EXPECT_NEAR(m.position.x - float(p.x), 2.4f, 0.25f);
  EXPECT_NEAR(m.position.y - float(p.y), -1.7f, 0.25f);
}
