#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/style_params.hpp"

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
