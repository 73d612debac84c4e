#pragma once
// Hatching tone layers (SPEC S7): tileable images of hatch strokes, from light to dark, where
// every lighter layer's strokes are a subset of every darker layer's (so tones blend without
// strokes jumping about). Up to a cross-hatching tone, layers add strokes in one direction;
// darker ones add strokes across them, as tonal art maps do.
#include <vector>

#include "common/image.hpp"

namespace inkwire {

struct HatchTones {
  std::vector<Image> layers;        // layers[0] lightest (paper only) ... back() darkest
  std::vector<int> strokes_in_layer;  // how many strokes each layer holds
  std::vector<int> crossing_in_layer;  // how many of them run across the first direction
};

// `layers` tones of one tile drawn at `size` x `size` texels (16..1024): the same strokes at
// any size. Strokes across the first direction appear only in layers darker than `cross_tone`
// (0..1; 1: never). Deterministic per seed.
inline constexpr float kHatchStrokeAngle = 0.75f, kCrossStrokeAngle = -0.6f;  // radians, in the tile
HatchTones make_hatch_tones(int layers = 8, int size = 128, uint32_t seed = 3, float cross_tone = 0.5f);

// The nested stack folded into one tileable image, so a tone costs one texture read (after
// Webb et al.'s threshold hatching). A texel's ink only grows from layer to layer; it is kept
// as the two steps that fit it best: red the tone where its ink first appears, green that
// ink's strength; blue the tone where it darkens, alpha the strength from there on. Texels no
// stroke reaches (strength 0) take the lowest tones of their nearest inked neighbours, so that
// filtering between a stroke and the paper beside it blends strengths, not tones: the stroke's
// own soft edge stays its edge. Throws inkwire::Error for fewer than two layers.
Image tone_thresholds(const HatchTones& tones);

// Fraction of a layer's texels covered by ink (alpha > 0.5).
double ink_coverage(const Image& layer);

}  // namespace inkwire
