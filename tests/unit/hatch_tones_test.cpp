// Hatch tone layers (SPEC S7) without GL: nested stroke sets, darkening monotonically.
#include <cmath>
#include <cstdio>

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
  EXPECT_THROW(make_hatch_tones(8, 8), Error);
  EXPECT_THROW(make_hatch_tones(8, 2048), Error);
}

TEST(HatchTonesTest, ThresholdsReproduceEveryLayer) {
  const HatchTones tones = make_hatch_tones(16, 64);
  const Image steps = tone_thresholds(tones);
  ASSERT_EQ(steps.width, 64);
  for (size_t k = 0; k < tones.layers.size(); ++k) {
    const float tone = float(k) / float(tones.layers.size() - 1);
    // The ink the shader reads at this layer's tone (texel centres, no softness).
    double error = 0.0;
    size_t inked = 0, inked_by_steps = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const uint8_t* t = steps.at(x, y);
        const float ink = (float(t[0]) / 255.0f <= tone ? float(t[1]) : 0.0f) + (float(t[2]) / 255.0f <= tone ? float(t[3]) - float(t[1]) : 0.0f);
        const float truth = tones.layers[k].at(x, y)[3];
        error += std::abs(ink - truth) / 255.0;
        inked += truth > 127;
        inked_by_steps += ink > 127;
      }
    const double mean_error = error / (64.0 * 64.0);
    std::printf("layer %2zu: mean ink error %.3f, inked %zu texels, by the steps %zu\n", k, mean_error, inked, inked_by_steps);
    // Two steps cannot follow a texel darkened by three or more strokes exactly (measured: at
    // most 0.003 of full ink per texel on average).
    EXPECT_LT(mean_error, 0.01) << "layer " << k;
    EXPECT_NEAR(double(inked_by_steps), double(inked), 0.05 * 64 * 64) << "layer " << k;
  }
  EXPECT_THROW(tone_thresholds(HatchTones{}), Error);
}

TEST(HatchTonesTest, AnySizeDrawsTheSameTile) {
  // The threshold image is drawn at the tile's size on screen, so the tones must not depend on
  // it: every layer's ink covers about the same share of the tile at 96 and 128 texels.
  const HatchTones small = make_hatch_tones(8, 96), large = make_hatch_tones(8, 128);
  for (size_t k = 1; k < small.layers.size(); ++k) {
    EXPECT_EQ(small.strokes_in_layer[k], large.strokes_in_layer[k]) << "layer " << k;
    EXPECT_NEAR(ink_coverage(small.layers[k]), ink_coverage(large.layers[k]), 0.03) << "layer " << k;
  }
}

TEST(HatchTonesTest, StrokesCrossOnlyInTonesDarkerThanTheCrossHatchingTone) {
  for (const float cross_tone : {0.3f, 0.5f, 0.8f}) {
    const HatchTones tones = make_hatch_tones(16, 64, 3, cross_tone);
    for (size_t k = 0; k < tones.layers.size(); ++k) {
      const float tone = float(k) / float(tones.layers.size() - 1);
      if (tone <= cross_tone) {
        EXPECT_EQ(tones.crossing_in_layer[k], 0) << "tone " << tone << " is lighter than " << cross_tone;
      } else if (tone > cross_tone + 0.1f) {
        EXPECT_GT(tones.crossing_in_layer[k], 0) << "tone " << tone << " is darker than " << cross_tone;
      }
    }
    EXPECT_GT(ink_coverage(tones.layers.back()), 0.4) << "the darkest tone is mostly ink";
  }
  const HatchTones one_way = make_hatch_tones(16, 64, 3, 1.0f);
  for (int n : one_way.crossing_in_layer) EXPECT_EQ(n, 0) << "a cross-hatching tone of 1 never crosses";
  EXPECT_THROW(make_hatch_tones(8, 64, 3, 1.5f), Error);
}
