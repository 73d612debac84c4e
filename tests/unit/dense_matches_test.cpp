// Dense verified matches and their distillation into control points (SPEC T15), and exposure
// evened across a product's photos (T19), without GL: a textured object that moves by a known,
// non-rigid motion between two photos.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "common/error.hpp"
#include "server/products/exposure.hpp"
#include "server/tween/dense_matches.hpp"

using namespace inkwire;

namespace {

constexpr int kSize = 256;

// A blotchy texture (detail at several scales) inside a disc, white outside; alpha is the matte.
Image textured_disc() {
  cv::Mat noise(kSize, kSize, CV_32FC3);
  cv::randu(noise, 0.0f, 1.0f);
  cv::Mat texture;
  cv::GaussianBlur(noise, texture, {0, 0}, 2.0);
  cv::normalize(texture, texture, 20, 235, cv::NORM_MINMAX);
  Image out(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool inside = std::hypot(x - 128.0, y - 128.0) < 90.0;
      const cv::Vec3f t = texture.at<cv::Vec3f>(y, x);
      uint8_t* p = out.at(x, y);
      for (int c = 0; c < 3; ++c) p[c] = inside ? uint8_t(t[c]) : 255;
      p[3] = inside ? 255 : 0;
    }
  return out;
}

// Where a pixel of the first photo is in the second: a shift that varies across the object (a
// third photo: `scale` times it).
cv::Vec2f motion(float x, float y, float scale = 1.0f) {
  return scale * cv::Vec2f(6.0f + 4.0f * std::sin(y / 40.0f), 2.0f * std::cos(x / 50.0f));
}

// `a` moved by motion() (sampled backward through its inverse, close enough for smooth motion).
Image moved(const Image& a, float scale = 1.0f) {
  cv::Mat map(kSize, kSize, CV_32FC2);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const cv::Vec2f m = motion(float(x), float(y), scale);
      const cv::Vec2f back = motion(float(x) - m[0], float(y) - m[1], scale);
      map.at<cv::Vec2f>(y, x) = {float(x) - back[0], float(y) - back[1]};
    }
  const cv::Mat source(kSize, kSize, CV_8UC4, const_cast<uint8_t*>(a.pixels.data()));
  cv::Mat out;
  cv::remap(source, out, map, {}, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255, 0));
  Image b(kSize, kSize);
  std::copy_n(out.ptr<uint8_t>(0), b.pixels.size(), b.pixels.data());
  return b;
}

}  // namespace

TEST(DenseMatchesTest, FlowFollowsATexturedObjectAndIsKeptOnlyWhereVerified) {
  const Image a = textured_disc(), b = moved(a);
  const DenseMatches m = dense_matches(a, b);
  int inside = 0, kept = 0;
  double error = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      if (a.at(x, y)[3] < 128) {
        EXPECT_EQ(m.reliable.at<uint8_t>(y, x), 0) << "backdrop at " << x << "," << y;
        continue;
      }
      ++inside;
      if (!m.reliable.at<uint8_t>(y, x)) continue;
      ++kept;
      const cv::Vec2f f = m.forward.at<cv::Vec2f>(y, x), truth = motion(float(x), float(y));
      error += std::hypot(f[0] - truth[0], f[1] - truth[1]);
    }
  std::printf("verified %d of %d object pixels, mean error %.3f px\n", kept, inside, error / kept);
  EXPECT_GT(kept, inside * 8 / 10);
  EXPECT_LT(error / kept, 0.5);
}

TEST(DenseMatchesTest, AFewPointsCarryTheFlowsAndGoWhereTheWarpWouldMissThem) {
  // A triangle's three photos: b moved one way, c (the row above, say) the other way and less.
  const Image a = textured_disc(), b = moved(a), c = moved(a, -0.6f);
  const DenseMatches to_b = dense_matches(a, b), to_c = dense_matches(a, c);
  DistilOptions options;
  options.max_points = 120;
  const std::vector<Track> points = distil_tracks({&to_b, &to_c}, a, {}, options);
  EXPECT_LE(points.size(), size_t(options.max_points));
  EXPECT_GE(points.size(), size_t(12));
  // The warp through the points follows each true motion inside the object.
  for (const float scale : {1.0f, -0.6f}) {
    std::vector<Landmark> through;
    for (const Track& t : points) through.push_back({.source = t.source, .target = t.targets[scale > 0 ? 0 : 1], .match = 1});
    const cv::Mat warp = warp_flow(through, {kSize, kSize});
    double error = 0, none = 0;
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        if (std::hypot(x - 128.0, y - 128.0) > 80.0) continue;
        const cv::Vec2f w = warp.at<cv::Vec2f>(y, x), truth = motion(float(x), float(y), scale);
        error += std::hypot(w[0] - truth[0], w[1] - truth[1]);
        none += std::hypot(truth[0], truth[1]);
        ++n;
      }
    std::printf("%zu points, motion x %.1f: warp error %.3f px (moving nothing: %.3f px)\n", points.size(), scale, error / n, none / n);
    EXPECT_LT(error / n, 0.6) << "motion x " << scale;
  }
  // Anchors are kept as they are, first.
  const Track anchor{.source = {20, 20}, .targets = {{21, 20}, {19, 20}}};
  const std::vector<Track> with_anchor = distil_tracks({&to_b, &to_c}, a, {anchor}, options);
  ASSERT_FALSE(with_anchor.empty());
  EXPECT_EQ(with_anchor.front().source, anchor.source);
  EXPECT_EQ(with_anchor.front().targets, anchor.targets);
  // Read the other way, the same matches lead back.
  const DenseMatches back = reversed(to_b);
  EXPECT_EQ(cv::norm(back.forward, to_b.backward, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(back.reliable, to_b.reliable_backward, cv::NORM_INF), 0.0);
}

TEST(DenseMatchesTest, FlowInterpolationPutsTheObjectHalfWay) {
  const Image a = textured_disc(), b = moved(a);
  const Image middle = flow_interpolation(a, b, 0.5f);
  // The object's centre of mass (its matte) moves half of the mean motion.
  auto centre_x = [](const Image& image) {
    double sum = 0, weight = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) sum += x * image.at(x, y)[3], weight += image.at(x, y)[3];
    return sum / weight;
  };
  const double from = centre_x(a), to = centre_x(b), mid = centre_x(middle);
  EXPECT_NEAR(mid, 0.5 * (from + to), 0.5);
  EXPECT_THROW(flow_interpolation(a, Image(10, 10), 0.5f), Error);
}

TEST(ExposureTest, APairsRatioIsReadFromItsMatchedPixels) {
  const Image a = textured_disc();
  Image b = a;
  apply_gain(b, glm::vec3(1.1f, 1.0f, 0.9f));
  const DenseMatches m = dense_matches(a, b);
  const PairExposure e = pair_exposure(m, a, b, 0, 1);
  ASSERT_GT(e.count, 0);
  EXPECT_NEAR(e.log_ratio.r, std::log(1.1f), 0.01);
  EXPECT_NEAR(e.log_ratio.g, 0.0f, 0.01);
  EXPECT_NEAR(e.log_ratio.b, std::log(0.9f), 0.01);
}

TEST(ExposureTest, APhotoBrighterThanItsNeighboursIsEvenedAndSlowLightIsKept) {
  // 24 photos round a ring: light that changes slowly as the product turns (+-5%), and photo
  // 3 shot 20% brighter.
  const int n = 24;
  std::vector<double> level(n);
  for (int i = 0; i < n; ++i) level[size_t(i)] = 0.05 * std::sin(2 * M_PI * i / n) + (i == 3 ? std::log(1.2) : 0.0);
  std::vector<PairExposure> pairs;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    pairs.push_back({.a = i, .b = j, .log_ratio = glm::vec3(float(level[size_t(j)] - level[size_t(i)])), .count = 1000});
  }
  const std::vector<glm::vec3> gains = exposure_gains(pairs, n, true);
  ASSERT_EQ(gains.size(), size_t(n));
  EXPECT_NEAR(gains[3].g, 1.0 / 1.2, 0.02);
  for (int i = 0; i < n; ++i) {
    if (i != 3) {
      EXPECT_NEAR(gains[size_t(i)].g, 1.0, 0.03) << "photo " << i << " keeps its light";
    }
  }
  // A pair without usable matches says nothing; a lone photo keeps its gain.
  EXPECT_EQ(exposure_gains({}, 3, false), std::vector<glm::vec3>(3, glm::vec3(1.0f)));
}
