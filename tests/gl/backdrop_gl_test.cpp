// Paper backdrop (SPEC G6) and hidden-line removal that preserves it (SPEC G7).
#include <algorithm>
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

TEST(BackdropTest, ParseRefusesUnknownSpecs) {
  EXPECT_EQ(BackdropSpec::parse("none").kind, BackdropSpec::Kind::None);
  EXPECT_EQ(BackdropSpec::parse("#ff0000").colour.r, 1.0f);
  EXPECT_THROW(BackdropSpec::parse("wallpaper"), Error);
  EXPECT_THROW(BackdropSpec::parse("#ff00"), Error);
}

TEST(HiddenLineGLTest, BackdropOutsideTheObjectIsUntouched) {
  INKWIRE_REQUIRE_FILE(test::cgal_mesh("cow.off"));
  test::offscreen_context();
  Canvas canvas(320, 240);  // no multisampling: every pixel is either paper or exact ink
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
      const bool ink = drawn.rgba(x, y) == glm::u8vec4(0, 0, 0, 255);
      other += !ink;
      // A 2-pixel line centred on the silhouette reaches one pixel past the mask, plus one
      // where the line and triangle rasterisation rules round differently.
      const bool near_object = test::near_covered(mask, x, y, 2);
      (near_object ? ink_inside : ink_outside) += ink;
    }
  EXPECT_EQ(other, 0u) << "pixels that are neither paper nor ink: the depth pass wrote colour";
  EXPECT_EQ(ink_outside, 0u) << "ink away from the object";
  EXPECT_GT(ink_inside, 500u) << "the drawing has too few lines";
  // Hidden lines really are removed: far fewer edges drawn than a see-through drawing needs.
  const auto counters = lines->counters();
  EXPECT_GT(counters.at("edges_drawn"), 50);
  EXPECT_LT(counters.at("edges_drawn"), counters.at("edges_total"));
}
