#pragma once
// Exposure and white balance evened across a product's photos (SPEC T19). A photo a little
// brighter or bluer than its neighbours flickers as the product turns. Each neighbouring pair's
// verified matches say how much brighter b is than a per channel (the median log ratio of
// matched pixels, clipped ones left out); per-photo levels that agree best with every pair (least
// squares) follow. Only a photo's departure from its neighbours' levels is evened (the median of
// the two on either side): light that changes slowly as the product turns (a side that faces
// the lamp) is the product's look, a photo that jumps is the camera's.
#include <vector>

#include <glm/vec3.hpp>

#include "common/image.hpp"
#include "server/tween/dense_matches.hpp"

namespace inkwire {

// Per channel, log(b / a) over the pair's verified matches; nullopt-like {0,0,0} with `count`
// 0 when too few matched pixels are usable.
struct PairExposure {
  int a = 0, b = 0;      // photo indices
  glm::vec3 log_ratio{0.0f};
  int count = 0;         // matched pixels used
};
PairExposure pair_exposure(const DenseMatches& matches, const Image& a, const Image& b, int index_a, int index_b);

// Per photo, the gain (per channel) that evens it with its neighbours in ring order (`closed`: the
// last photo's neighbours include the first). Photos no pair reaches keep 1.
std::vector<glm::vec3> exposure_gains(const std::vector<PairExposure>& pairs, int photos, bool closed);

// Multiplies the colours (not the matte) by `gain`, clamped to 0-255, where the matte is not 0
// (the floor layer there is already relative to the photo's own backdrop).
void apply_gain(Image& photo, const glm::vec3& gain);

}  // namespace inkwire
