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

// `layers` tones of `size` x `size` texels (size a power of two). Deterministic per seed.
HatchTones make_hatch_tones(int layers = 8, int size = 128, uint32_t seed = 3);

// Fraction of a layer's texels covered by ink (alpha > 0.5).
double ink_coverage(const Image& layer);

}  // namespace inkwire
