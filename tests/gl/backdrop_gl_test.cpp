// Paper backdrop (SPEC G6) and hidden-line removal that preserves it (SPEC G7).
#include <algorithm>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "client/gl/canvas.hpp"
#include "common/error.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/styles.hpp"
#include "gl_test_support.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;

TEST(BackdropTest, PaperTilesSeamlessly) {
  const Image paper = generate_paper(128, 3);
  // Across the wrap, neighbouring texels differ no more than neighbours inside the tile do.
  auto step = [&](int x0, int y0, int x1, int y1) { return std::abs(int(paper.at(x0, y0)[1]) - int(paper.at(x1, y1)[1])); };
  double inside = 0, across = 0;
  for (int y = 0; y < 128; ++y) {
    inside += step(63, y, 64, y);
    across += step(127, y, 0, y);
  }
  EXPECT_LT(across, inside * 2.0 + 128) << "visible seam at the tile edge";
  std::set<int> tones;
  for (size_t i = 0; i < paper.pixels.size(); i += 4) tones.insert(paper.pixels[i]);
  EXPECT_GE(tones.size(), 6u) << "paper should have grain, not a flat colour";
}

TEST(BackdropGLTest, PaperFileLiesOneTexelPerPixelWhateverItsShape) {
  test::offscreen_context();
  // A 6 x 4 paper whose every texel has its own colour.
  Image paper(6, 4);
  std::set<uint32_t> texels;
  for (int y = 0; y < paper.height; ++y)
    for (int x = 0; x < paper.width; ++x) {
      uint8_t* p = paper.at(x, y);
      p[0] = uint8_t(40 * x), p[1] = uint8_t(60 * y), p[2] = 99, p[3] = 255;
      texels.insert(uint32_t(p[0]) << 8 | p[1]);
    }
  const std::filesystem::path file = test::scratch_dir() / "paper-6x4.png";
  save_image(paper, file);
  Canvas canvas(48, 32);
  canvas.bind();
  Backdrop(BackdropSpec::parse("paper:" + file.string())).draw();
  const Image drawn = canvas.read();
  std::filesystem::remove(file);
  size_t not_a_texel = 0, off_period = 0;
  for (int y = 0; y < drawn.height; ++y)
    for (int x = 0; x < drawn.width; ++x) {
      const uint8_t* p = drawn.at(x, y);
      not_a_texel += !texels.count(uint32_t(p[0]) << 8 | p[1]);
      off_period += (x + 6 < drawn.width && drawn.rgba(x, y) != drawn.rgba(x + 6, y)) ||
                    (y + 4 < drawn.height && drawn.rgba(x, y) != drawn.rgba(x, y + 4));
    }
  EXPECT_EQ(not_a_texel, 0u) << "pixels blended between texels";
  EXPECT_EQ(off_period, 0u) << "the paper does not repeat every 6 x 4 pixels: stretched";
}

TEST(BackdropTest, ParseRefusesUnknownSpecs) {
  EXPECT_EQ(BackdropSpec::parse("none").kind, BackdropSpec::Kind::None);
  EXPECT_EQ(BackdropSpec::parse("#ff0000").colour.r, 1.0f);
  EXPECT_THROW(BackdropSpec::parse("wallpaper"), Error);
  EXPECT_THROW(BackdropSpec::parse("#ff00"), Error);
}

TEST(HiddenLineGLTest, BackdropOutsideTheObjectIsUntouched) {
  INKWIRE_REQUIRE_FILE(test::cgal_mesh("cow.off"));
  test::offscreen_context();
  Canvas canvas(320, 240);  // no multisampling: every pixel is paper, ink, or ink blended over paper by coverage
  SceneObject cow = load_scene_object(test::cgal_mesh("cow.off"));
  FrameState frame;
  frame.viewport = canvas.size();
  frame.camera = orbit_camera(cow.topology.bounds, 35, 15, 1.2f);
  frame.light_direction = default_light_direction(frame.camera);

  // The object's mask, from the default renderer over a transparent clear.
  auto shaded = make_renderer("default");
  shaded->prepare(cow);
  canvas.bind();
  Backdrop(BackdropSpec::parse("none")).draw();
  shaded->draw(frame);
  const Image mask = canvas.read();

  const Backdrop paper(BackdropSpec::parse("paper"));
  canvas.bind();
  paper.draw();
  const Image paper_only = canvas.read();

  auto lines = make_renderer("hidden-line", {"line_width=2", "colour=#000000"});
  lines->prepare(cow);
  canvas.bind();
  paper.draw();
  lines->draw(frame);
  const Image drawn = canvas.read();

  size_t ink_inside = 0, ink_outside = 0, other = 0;
  for (int y = 0; y < drawn.height; ++y)
    for (int x = 0; x < drawn.width; ++x) {
      if (drawn.rgba(x, y) == paper_only.rgba(x, y)) continue;
      // Black ink over paper at some coverage: every channel the paper's times one factor.
      const glm::vec4 d(drawn.rgba(x, y)), p(paper_only.rgba(x, y));
      const float k = (d.r + d.g + d.b) / std::max(p.r + p.g + p.b, 1.0f);
      const bool ink = std::abs(d.r - k * p.r) <= 3 && std::abs(d.g - k * p.g) <= 3 && std::abs(d.b - k * p.b) <= 3 && d.a == 255;
      other += !ink;
      // A 2-pixel line centred on the silhouette reaches one pixel past the mask, plus one
      // where the line and triangle rasterisation rules round differently.
      const bool near_object = test::near_covered(mask, x, y, 2);
      (near_object ? ink_inside : ink_outside) += ink;
    }
  EXPECT_EQ(other, 0u) << "pixels that are neither paper nor ink over it: the depth pass wrote colour";
  EXPECT_EQ(ink_outside, 0u) << "ink away from the object";
  EXPECT_GT(ink_inside, 500u) << "the drawing has too few lines";
  // Hidden lines really are removed: far fewer edges drawn than a see-through drawing needs.
  const auto counters = lines->counters();
  EXPECT_GT(counters.at("edges_drawn"), 50);
  EXPECT_LT(counters.at("edges_drawn"), counters.at("edges_total"));
}
