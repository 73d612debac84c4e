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

TEST(ExposureTest, APhotoWhoseBackdropJumpsIsEvenedAndSlowDriftIsKept) {
  // 24 photos round a ring over a grey backdrop: daylight that drifts slowly (+-5%), and photo 3
  // shot 20% brighter and bluer by the camera.
  const int n = 24;
  std::vector<glm::vec3> backdrops;
  for (int i = 0; i < n; ++i) {
    const float light = 180.0f * std::exp(0.05f * std::sin(2.0f * float(M_PI) * float(i) / float(n)));
    backdrops.push_back(i == 3 ? glm::vec3(1.2f, 1.2f, 1.3f) * light : glm::vec3(light));
  }
  const CameraGains camera = camera_gains(backdrops, true);
  ASSERT_EQ(camera.gains.size(), size_t(n));
  EXPECT_TRUE(camera.unmeasured.empty());
  EXPECT_NEAR(camera.gains[3].g, 1.0 / 1.2, 0.02);
  EXPECT_NEAR(camera.gains[3].b, 1.0 / 1.3, 0.02);
  for (int i = 0; i < n; ++i) {
    if (i != 3) {
      EXPECT_NEAR(camera.gains[size_t(i)].g, 1.0, 0.01) << "photo " << i << " keeps its light";
    }
  }
}

TEST(ExposureTest, ABackdropWhiteToTheClipEvensNothingAndSaysWhy) {
  // A rendered product over white: the backdrop shows no exposure, so nothing is touched, even
  // where the object's own shading changes from photo to photo.
  const CameraGains camera = camera_gains(std::vector<glm::vec3>(12, glm::vec3(255.0f)), true);
  EXPECT_EQ(camera.gains, std::vector<glm::vec3>(12, glm::vec3(1.0f)));
  EXPECT_NE(camera.unmeasured.find("white to the clip"), std::string::npos) << camera.unmeasured;
  EXPECT_FALSE(camera_gains({glm::vec3(100.0f), glm::vec3(120.0f)}, false).unmeasured.empty()) << "two photos show no trend";
}
