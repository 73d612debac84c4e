// The comic shade-map library (SPEC C1, C3, C4), checked as images without GL.
#include <set>

#include <gtest/gtest.h>

#include "client/render/comic/shade_maps.hpp"
#include "common/error.hpp"

using namespace inkwire;

namespace {

std::set<uint32_t> row_values(const Image& img, int y) {
  std::set<uint32_t> values;
  for (int x = 0; x < img.width; ++x) {
    const glm::u8vec4 t = img.rgba(x, y);
    values.insert(uint32_t(t.r) << 16 | uint32_t(t.g) << 8 | t.b);
  }
  return values;
}

}  // namespace

TEST(ShadeMapTest, ComicMapHasExactlyTheRequestedBands) {
  for (int bands = 1; bands <= 6; ++bands) {
    ShadeMapOptions o;
    o.bands = bands;
    const Image img = make_shade_map("comic", o).image;
    EXPECT_EQ(row_values(img, img.height - 1).size(), size_t(bands)) << bands << " bands";  // R.V = 0 row
  }
}

TEST(ShadeMapTest, TwoToneShadowIsTenToThirtyPercentDarker) {
  const Image img = make_shade_map("two-tone").image;
  const int bottom = img.height - 1;
  const float shadow = img.rgba(0, bottom).g / 128.0f, lit = img.rgba(img.width - 1, bottom).g / 128.0f;
  EXPECT_NEAR(lit, 1.0f, 0.01f);
  EXPECT_GE(1.0f - shadow / lit, 0.10f);
  EXPECT_LE(1.0f - shadow / lit, 0.30f);
}

TEST(ShadeMapTest, BandEdgesSetBandSizes) {
  ShadeMapOptions o;
  o.bands = 2;
  o.band_edges = {0.75f};
  const Image img = make_shade_map("comic", o).image;
  const int bottom = img.height - 1;
  EXPECT_EQ(img.rgba(int(0.70f * img.width), bottom), img.rgba(0, bottom)) << "N.L 0.7 is still in the shadow band";
  EXPECT_NE(img.rgba(int(0.80f * img.width), bottom), img.rgba(0, bottom));
  o.band_edges = {0.5f, 0.2f};
  EXPECT_THROW(make_shade_map("comic", o), Error) << "wrong count";
  o.bands = 3;
  EXPECT_THROW(make_shade_map("comic", o), Error) << "not rising";
}

TEST(ShadeMapTest, HighlightOnlyWhereReflectionIsStrong) {
  const Image img = make_shade_map("comic").image;
  EXPECT_GT(img.rgba(img.width - 1, 0).r, 128) << "lit, R.V = 1: lifted toward white";
  for (int x = 0; x < img.width; ++x) EXPECT_LE(img.rgba(x, img.height - 1).r, 128) << "R.V = 0 never lifts";
}

TEST(ShadeMapTest, LinesMapSeparatesBandsWithBlack) {
  const Image img = make_shade_map("lines").image;
  const auto values = row_values(img, img.height - 1);
  EXPECT_TRUE(values.count(0)) << "black separators";
  EXPECT_EQ(values.size(), 4u) << "three bands and black";
}

TEST(ShadeMapTest, CheckerCrossesOver) {
  const Image img = make_shade_map("checker").image;
  const int w = img.width, h = img.height;
  EXPECT_NE(img.rgba(w / 8, h - 1), img.rgba(3 * w / 8, h - 1)) << "alternates along N.L";
  EXPECT_NE(img.rgba(w / 8, h - 1), img.rgba(w / 8, h - 1 - h / 4)) << "alternates along R.V";
}

TEST(ShadeMapTest, WarmCoolIsColoured) {
  const Image img = make_shade_map("warm-cool").image;
  const glm::u8vec4 shadow = img.rgba(0, img.height - 1);
  EXPECT_GT(shadow.b, shadow.r) << "cool shadow";
}

TEST(ShadeMapTest, EveryNamedMapBuildsAndUnknownIsRefused) {
  for (const auto& name : shade_map_names()) EXPECT_FALSE(make_shade_map(name).image.empty()) << name;
  EXPECT_THROW(make_shade_map("sepia"), Error);
}
