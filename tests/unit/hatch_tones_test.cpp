// Hatch tone layers (SPEC S7) without GL: nested stroke sets, darkening monotonically.
#include <gtest/gtest.h>

#include "client/render/hatching/hatch_tones.hpp"
#include "common/error.hpp"

using namespace inkwire;

TEST(HatchTonesTest, LighterLayersAreSubsetsOfDarkerOnes) {
  const HatchTones tones = make_hatch_tones(8, 64);
  ASSERT_EQ(tones.layers.size(), 8u);
  EXPECT_EQ(ink_coverage(tones.layers.front()), 0.0) << "the lightest tone is bare paper";
  for (size_t k = 0; k + 1 < tones.layers.size(); ++k) {
    EXPECT_LE(tones.strokes_in_layer[k], tones.strokes_in_layer[k + 1]);
    const Image &light = tones.layers[k], &dark = tones.layers[k + 1];
    // Every mark of the lighter layer is in the darker one (alpha never drops).
    for (size_t i = 3; i < light.pixels.size(); i += 4) ASSERT_LE(light.pixels[i], dark.pixels[i]) << "layer " << k;
    EXPECT_LT(ink_coverage(light), ink_coverage(dark)) << "layer " << k << " should be lighter than " << k + 1;
  }
  EXPECT_GT(ink_coverage(tones.layers.back()), 0.4) << "the darkest tone is mostly ink";
}

TEST(HatchTonesTest, BadSizesAreRefused) {
  EXPECT_THROW(make_hatch_tones(1, 64), Error);
  EXPECT_THROW(make_hatch_tones(8, 100), Error);
}
