#pragma once
// Hatching tone layers (SPEC S7): tileable images of hatch strokes, from light to dark, where
// every lighter layer's strokes are a subset of every darker layer's (so tones blend without
// strokes jumping about). Darker layers add strokes in the same direction, then cross-hatch.
#include <vector>

#include "common/image.hpp"

namespace inkwire {

struct HatchTones {
  std::vector<Image> layers;        // layers[0] lightest (paper only) ... back() darkest
  std::vector<int> strokes_in_layer;  // how many strokes each layer holds
};

// `layers` tones of one tile drawn at `size` x `size` texels (16..1024): the same strokes at
// any size. Deterministic per seed.
HatchTones make_hatch_tones(int layers = 8, int size = 128, uint32_t seed = 3);

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
