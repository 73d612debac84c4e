#include <algorithm>
#include <gtest/gtest.h>

#include "client/render/painterly/paint_style.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"
#include "common/style_params.hpp"
#include "test_data.hpp"

using namespace inkwire;

namespace {
StyleParams sample() {
  return StyleParams({float_param("width", "2", 1, 10, "w"), int_param("k", "1", 1, 3, "k"),
                      bool_param("fade", "true", "f"), colour_param("ink", "#102030", "c"),
                      choice_param("mode", "vertex", {"triangle", "vertex"}, "m")});
}
}  // namespace

TEST(StyleParamsTest, DefaultsAndTypedValues) {
  StyleParams p = sample();
  EXPECT_FLOAT_EQ(p.get_float("width"), 2.0f);
  EXPECT_EQ(p.get_int("k"), 1);
  EXPECT_TRUE(p.get_bool("fade"));
  EXPECT_NEAR(p.get_colour("ink").g, 32.0f / 255.0f, 1e-6);
  p.set_assignment("mode=triangle");
  EXPECT_EQ(p.get_text("mode"), "triangle");
}

TEST(StyleParamsTest, BadValuesAreRefusedWithReasons) {
  StyleParams p = sample();
  EXPECT_THROW(p.set("width", "11"), Error);
  EXPECT_THROW(p.set("width", "nan"), Error);
  EXPECT_THROW(p.set("width", "2px"), Error);
  EXPECT_THROW(p.set("k", "1.5"), Error);
  EXPECT_THROW(p.set("fade", "maybe"), Error);
  EXPECT_THROW(p.set("ink", "#12345"), Error);
  EXPECT_THROW(p.set("mode", "edge"), Error);
  EXPECT_THROW(p.set_assignment("width"), Error);
  try {
    p.set("nope", "1");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("known: width|k|fade|ink|mode"), std::string::npos) << e.what();
  }
  EXPECT_FLOAT_EQ(p.get_float("width"), 2.0f) << "a refused value must not change the old one";
}

// What make_renderer() would be configured with, checked without making one (no GL needed):
// how a client checks a conference's style, which draws no mesh.
TEST(StyleParamsTest, StyleChecksWithoutARendererRefuseWhatMakeRendererWould) {
  const auto parts = style_params("hatching+sketch-charcoal", {"angle=30", "fade=false"});
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_FLOAT_EQ(parts[0].get_float("angle"), 30.0f);
  EXPECT_FALSE(parts[1].get_bool("fade"));
  EXPECT_EQ(test::error_of([] { style_params("no-such-style"); }).find("unknown style 'no-such-style'"), 0u);
  EXPECT_NE(test::error_of([] { style_params("painterly", {"no_such_key=1"}); }), "");
  EXPECT_NE(test::error_of([] { style_params("comic", {"outline_width=-4"}); }), "");
}

TEST(StyleParamsTest, AJoinedStyleListsEveryPartsParametersOnce) {
  // What the windowed client's parameter panel shows for a session's style.
  auto names_of = [](const std::vector<ParamSpec>& specs) {
    std::vector<std::string> names;
    for (const ParamSpec& p : specs) names.push_back(p.name);
    return names;
  };
  const auto hatching = names_of(style_param_specs("hatching")), pencil = names_of(style_param_specs("sketch-pencil"));
  const auto joined = names_of(style_param_specs("hatching+sketch-pencil"));
  for (const auto* part : {&hatching, &pencil})
    for (const std::string& name : *part) EXPECT_EQ(std::count(joined.begin(), joined.end(), name), 1) << name;
  EXPECT_EQ(test::error_of([] { style_param_specs("hatching+no-such-style"); }).find("unknown style 'no-such-style'"), 0u);
}

// What a panel shows: the values a style really uses, never "0 takes the style file's".
TEST(StyleSettingsInEffectTest, PainterlyPlaceholdersShowTheStyleFilesValues) {
  const PaintStyle pointillist = load_paint_style("pointillist");
  const auto values = style_settings_in_effect("painterly", {"style=pointillist"});
  EXPECT_EQ(values.at("brushes"), std::to_string(pointillist.brushes));
  EXPECT_NE(values.at("brushes"), "0");
  EXPECT_NE(values.at("ttl"), "0");
  EXPECT_NE(values.at("underpaint"), "-1");
  EXPECT_NE(values.at("palette"), "style");
  // A value the user set wins over the file's.
  EXPECT_EQ(style_settings_in_effect("painterly", {"style=pointillist", "brushes=123"}).at("brushes"), "123");
}

TEST(StyleSettingsInEffectTest, JoinedStylesListEveryPartsValuesAndRefuseUnknownKeys) {
  const auto values = style_settings_in_effect("hatching+sketch-pencil", {"variant=multipass"});
  EXPECT_EQ(values.at("variant"), "multipass");
  EXPECT_TRUE(values.count("texture_length")) << "the pencil outline's parameters are listed too";
  EXPECT_THROW(style_settings_in_effect("comic", {"no_such_key=1"}), Error);
}

TEST(StyleRedrawRateTest, StillStylesNeedNoRedrawAndAnimatedOnesTheirRate) {
  EXPECT_EQ(style_redraw_hz("comic"), 0.0);
  EXPECT_EQ(style_redraw_hz("tween"), 0.0);
  EXPECT_GT(style_redraw_hz("sketch-recursive"), 0.0);
  EXPECT_GT(style_redraw_hz("painterly"), 0.0);
  EXPECT_EQ(style_redraw_hz("hatching+sketch-segments"), style_redraw_hz("sketch-segments"));
}
