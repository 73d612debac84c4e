// The painterly brushes without GL (SPEC P4-P8): motion and home-seeking against a matte,
// respawns, automatic size, colour averaging, palettes, style files and the oil filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

#include <glm/geometric.hpp>

#include "client/render/painterly/brush_field.hpp"
#include "client/render/painterly/brush_shapes.hpp"
#include "client/render/painterly/oil_filter.hpp"
#include "client/render/painterly/paint_style.hpp"
#include "client/render/painterly/palette.hpp"
#include "common/error.hpp"

using namespace inkwire;

namespace {

// A disc of `radius` (unit square) in a `size` x `size` capture: the object.
Matte disc_matte(int size, float radius, glm::vec2 centre = {0.5f, 0.5f}) {
  std::vector<uint8_t> inside(size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec2 p((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
      inside[size_t(y) * size + x] = glm::length(p - centre) < radius;
    }
  return Matte(size, size, std::move(inside));
}

// Vertical bars `bar` pixels wide with gaps as wide: an object that is mostly outline, like a
// herd's legs.
Matte bars_matte(int size, int bar) {
  std::vector<uint8_t> inside(size_t(size) * size);
  for (int y = size / 8; y < size - size / 8; ++y)
    for (int x = size / 8; x < size - size / 8; ++x) inside[size_t(y) * size + x] = (x / bar) % 2 == 0;
  return Matte(size, size, std::move(inside));
}

// Object pixels under at least one visible brush, each drawn as the ellipse inscribed in its
// quad (the shapes' paint fills less than the quad; the ellipse is the conservative footprint).
double painted_fraction(const BrushField& field, const Matte& matte, float side, float aspect) {
  const float half_length = 0.5f * side * std::sqrt(aspect), half_width = 0.5f * side / std::sqrt(aspect);
  std::vector<uint8_t> painted(size_t(matte.width()) * matte.height(), 0);
  for (const Brush& b : field.brushes()) {
    if (!b.visible) continue;
    const glm::vec2 centre = b.position * glm::vec2(matte.width(), matte.height());
    const glm::vec2 along(std::cos(b.angle), std::sin(b.angle)), across(-along.y, along.x);
    const int reach = int(std::ceil(half_length)) + 1;
    for (int y = int(centre.y) - reach; y <= int(centre.y) + reach; ++y)
      for (int x = int(centre.x) - reach; x <= int(centre.x) + reach; ++x) {
        if (x < 0 || y < 0 || x >= matte.width() || y >= matte.height()) continue;
        const glm::vec2 d = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - centre;
        const float u = glm::dot(d, along) / half_length, v = glm::dot(d, across) / half_width;
        if (u * u + v * v <= 1.0f) painted[size_t(y) * matte.width() + x] = 1;
      }
  }
  size_t covered = 0;
  for (int y = 0; y < matte.height(); ++y)
    for (int x = 0; x < matte.width(); ++x) covered += matte.covers_pixel(x, y) && painted[size_t(y) * matte.width() + x];
  return double(covered) / double(matte.object_pixels());
}

}  // namespace

TEST(BrushFieldTest, MatteCountsObjectPixelsAndRefusesTheOutsideOfTheUnitSquare) {
  const Matte m = disc_matte(200, 0.3f);
  EXPECT_NEAR(m.object_fraction(), 3.14159 * 0.09, 0.01);
  EXPECT_TRUE(m.covers({0.5f, 0.5f}));
  EXPECT_FALSE(m.covers({0.05f, 0.05f}));
  EXPECT_FALSE(m.covers({-0.1f, 0.5f}));
  EXPECT_FALSE(m.covers({0.5f, 1.0f}));
  EXPECT_FALSE(m.covers({std::nanf(""), 0.5f}));
  EXPECT_THROW(Matte(10, 10, std::vector<uint8_t>(99)), Error);
}

TEST(BrushFieldTest, StaticObjectVisibleFractionRisesFromObjectFractionToNinetyFivePercent) {
  const Matte matte = disc_matte(200, 0.3f);  // P_A about 0.28
  BrushField field(2000, MotionSettings{}, 42);
  field.step(matte);
  EXPECT_NEAR(field.visible_fraction(), matte.object_fraction(), 0.05) << "brushes start anywhere in the capture";
  for (int frame = 1; frame < 100; ++frame) field.step(matte);
  EXPECT_GE(field.visible_fraction(), 0.95) << "lost brushes turn round or respawn until they find the object";
}

TEST(BrushFieldTest, VisibleBrushesAreOnTheObjectAndLostOnesAreNot) {
  const Matte matte = disc_matte(160, 0.25f, {0.4f, 0.6f});
  BrushField field(1000, MotionSettings{}, 3);
  for (int frame = 0; frame < 50; ++frame) {
    field.step(matte);
    for (const Brush& b : field.brushes()) {
      ASSERT_EQ(b.visible, matte.covers(b.position));
      ASSERT_EQ(b.ttl == 0, b.visible) << "a lost brush always has time left to search";
    }
  }
}

TEST(BrushFieldTest, RandomisedTimeToLiveSpreadsRespawnsAndAFixedOneSpikes) {
  const Matte matte = disc_matte(200, 0.3f);
  auto worst_frame = [&](bool randomise) {
    MotionSettings motion;
    motion.randomise_ttl = randomise;
    BrushField field(4000, motion, 9);
    double worst = 0;
    for (int frame = 0; frame < 100; ++frame) worst = std::max(worst, (field.step(matte), field.respawn_fraction()));
    return worst;
  };
  // About 72% of the brushes start off the object. With one time-to-live most of those that do
  // not find their way back respawn on the same frame; spread over 1..19 frames, no frame sees
  // more than a few percent.
  const double randomised = worst_frame(true), fixed = worst_frame(false);
  EXPECT_LE(randomised, 0.08) << "randomised time-to-live should keep respawns below 8% of the brushes per frame";
  EXPECT_GE(fixed, 0.25) << "a fixed time-to-live should respawn a synchronised wave";
}

// Random brushes leave gaps in clumps a brush wide, so the painted share varies by a percent
// from one scatter to the next around what the size aims at (measured 97.7-98.6% aiming at
// 98%). Aiming at 99%, every scatter must reach 98%, and on average the aim.
TEST(BrushFieldTest, AutomaticSizePaintsNinetyEightPercentOfTheObject) {
  struct Case {
    const char* name;
    Matte matte;
    float most_overlap;  // over the interior's: the outline's share
  };
  const Case cases[] = {{"disc", disc_matte(240, 0.32f), 1.1f}, {"bars", bars_matte(240, 12), 1.6f}};
  for (const Case& c : cases) {
    double sum = 0.0;
    int runs = 0;
    for (const float aspect : {1.0f, 3.0f})
      for (const uint64_t seed : {5u, 6u, 7u}) {
        BrushField field(2000, MotionSettings{}, seed);
        for (int frame = 0; frame < 100; ++frame) field.step(c.matte);
        for (Brush& b : field.brushes()) b.angle = float(&b - field.brushes().data()) * 0.7f;  // any slant
        const float side = automatic_brush_side(c.matte, field.last_step().visible, 0.99f);
        // A_B = P_A * A / visible brushes, times the interior's overlap and a little more for
        // the outline.
        const float overlap = side * side * float(field.last_step().visible) / float(c.matte.object_pixels());
        EXPECT_GT(overlap, overlap_for_coverage(0.99f)) << c.name;
        EXPECT_LT(overlap, c.most_overlap * overlap_for_coverage(0.99f)) << c.name;
        const double painted = painted_fraction(field, c.matte, side, aspect);
        EXPECT_GE(painted, 0.98) << c.name << ", aspect " << aspect << ", seed " << seed;
        sum += painted;
        ++runs;
      }
    std::printf("%s: %.4f painted on average\n", c.name, sum / runs);
    EXPECT_GE(sum / runs, 0.985) << c.name;
  }
}

TEST(BrushFieldTest, ColoursAreAveragedOverTheLastFrames) {
  const Matte matte = disc_matte(64, 0.45f);
  BrushField field(200, MotionSettings{.max_speed = 0.0f, .jitter = 0.0f}, 1, 4);
  const Image red(64, 64, {255, 0, 0, 255}), blue(64, 64, {0, 0, 255, 255});
  field.step(matte);
  std::vector<size_t> still;  // brushes on the object from the first frame (the others respawn)
  for (size_t i = 0; i < field.brushes().size(); ++i)
    if (field.brushes()[i].visible) still.push_back(i);
  ASSERT_GT(still.size(), 50u);
  field.sample_colours(red);
  for (int i = 0; i < 2; ++i) field.step(matte), field.sample_colours(red);
  field.step(matte);
  field.sample_colours(blue);
  for (const size_t i : still) {
    EXPECT_NEAR(field.brushes()[i].colour.r, 0.75f, 1e-4f);  // three red frames and one blue of four
    EXPECT_NEAR(field.brushes()[i].colour.b, 0.25f, 1e-4f);
  }
  for (int i = 0; i < 4; ++i) field.step(matte), field.sample_colours(blue);
  for (const size_t i : still) EXPECT_NEAR(field.brushes()[i].colour.b, 1.0f, 1e-4f) << "older frames drop out of the mean";
}

class PaletteShadesTest : public testing::TestWithParam<int> {};

TEST_P(PaletteShadesTest, QuantisingToNShadesYieldsExactlyNColours) {
  const int n = GetParam();
  Palette palette;
  palette.kind = PaletteKind::Shades;
  palette.shades = n;
  palette.tint = {1.0f, 0.9f, 0.7f};
  std::set<std::tuple<int, int, int>> seen;
  Random random(n);
  for (int i = 0; i <= 4096; ++i) {
    const glm::vec3 rgb = i <= 255 ? glm::vec3(float(i) / 255.0f) : glm::vec3(random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1));
    const glm::vec3 out = palette.apply(rgb);
    seen.insert({int(out.r * 1e4f), int(out.g * 1e4f), int(out.b * 1e4f)});
  }
  EXPECT_EQ(seen.size(), size_t(n));
}
INSTANTIATE_TEST_SUITE_P(Shades, PaletteShadesTest, testing::Values(2, 3, 6, 16));

TEST(PaletteTest, PosteriseLevelsEachChannelAndLookupFollowsItsRamp) {
  Palette p;
  p.kind = PaletteKind::Posterise;
  p.shades = 3;
  const glm::vec3 out = p.apply({0.1f, 0.5f, 0.95f});
  EXPECT_EQ(out, glm::vec3(0.0f, 0.5f, 1.0f));
  Palette lookup;
  lookup.kind = PaletteKind::Lookup;
  lookup.ramp = {{0, 0, 1}, {1, 0, 0}};
  EXPECT_EQ(lookup.apply(glm::vec3(0)), glm::vec3(0, 0, 1));
  EXPECT_EQ(lookup.apply(glm::vec3(1)), glm::vec3(1, 0, 0));
  EXPECT_THROW(palette_kind("pastel"), Error);
}

TEST(PaintStyleTest, ShippedStylesParse) {
  const std::vector<std::string> shipped = shipped_paint_styles();
  EXPECT_GE(shipped.size(), 3u);
  for (const std::string& name : shipped) {
    const PaintStyle s = load_paint_style(name);
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.shapes.empty());
  }
  const PaintStyle pointillist = load_paint_style("pointillist");
  EXPECT_EQ(pointillist.shapes, std::vector<BrushShape>{BrushShape::Dot});
  EXPECT_EQ(pointillist.orientation.kind, OrientationKind::Random);
}

TEST(PaintStyleTest, RulesPickByRegionColour) {
  const PaintStyle s = parse_paint_style(R"({"regions": [{"when": {"luminance": [0, 0.3]}, "shapes": ["blotch"], "size": 2},
                                                          {"when": {"saturation": [0.5, 1]}, "opacity": 0.4}]})", "test");
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_TRUE(s.regions[0].matches({0.1f, 0.1f, 0.1f}));
  EXPECT_FALSE(s.regions[0].matches({0.9f, 0.9f, 0.9f}));
  EXPECT_TRUE(s.regions[1].matches({0.9f, 0.1f, 0.1f}));
  EXPECT_FALSE(s.regions[1].matches({0.8f, 0.8f, 0.8f}));
  EXPECT_EQ(s.regions[0].shapes, std::vector<BrushShape>{BrushShape::Blotch});
}

TEST(PaintStyleTest, BadStyleFilesAreRefusedWithTheReason) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"brushes": 3000)", "not JSON"},
      {R"({"brush": 3000})", "'brush' is not a known key"},
      {R"({"brushes": -5})", "'brushes' must be within"},
      {R"({"brushes": "many"})", "'brushes' must be a whole number"},
      {R"({"shapes": ["feather"]})", "unknown brush shape 'feather'"},
      {R"({"palette": {"kind": "pastel"}})", "unknown palette 'pastel'"},
      {R"({"palette": {"kind": "lookup"}})", "is needed by a lookup palette"},
      {R"({"orientation": {"kind": "spiral"}})", "must be random, constant, circular or gradient"},
      {R"({"regions": [{"when": {"luminance": [0.8, 0.2]}}]})", "0 <= min <= max <= 1"},
      {R"([1, 2, 3])", "must be an object"},
  };
  for (const auto& [text, reason] : cases) {
    try {
      parse_paint_style(text, "case.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    }
  }
  EXPECT_THROW(load_paint_style("no-such-style"), Error);
}

TEST(BrushShapesTest, StrokesThinOutAlongTheirLength) {
  const Image stroke = make_brush_texture(BrushShape::Stroke);
  auto column_alpha = [&](int x) {
    double sum = 0;
    for (int y = 0; y < stroke.height; ++y) sum += stroke.at(x, y)[3];
    return sum;
  };
  const int n = stroke.width;
  EXPECT_GT(column_alpha(n / 5), 1.5 * column_alpha(n * 4 / 5)) << "paint runs out toward the end of the stroke";
  for (const Image& shape : make_brush_textures()) {
    EXPECT_EQ(shape.width, kBrushTextureSize);
    EXPECT_EQ(shape.at(0, 0)[3], 0) << "corners stay clear: a brush is not a square";
  }
}

TEST(OilFilterTest, KeepsFlatRegionsAndEdgesAndIgnoresTheBackground) {
  Image image(40, 40, {0, 0, 0, 0});
  for (int y = 5; y < 35; ++y)
    for (int x = 5; x < 35; ++x) {
      uint8_t* p = image.at(x, y);
      p[0] = x < 20 ? 200 : 40, p[1] = 60, p[2] = 30, p[3] = 255;
    }
  image.at(10, 10)[0] = 0;  // a speck the filter removes
  const Image out = oil_filter(image, 3, 16);
  EXPECT_EQ(out.at(10, 10)[0], 200) << "an outlier loses the vote to its neighbours";
  EXPECT_EQ(out.at(18, 20)[0], 200);
  EXPECT_EQ(out.at(21, 20)[0], 40) << "the edge stays where it was";
  EXPECT_EQ(out.at(2, 2)[3], 0) << "background untouched";
  EXPECT_THROW(oil_filter(image, 0, 16), Error);
  EXPECT_THROW(oil_filter(image, 3, 1), Error);
}
