#pragma once
// Exact Euclidean distances from every pixel's centre to the nearest seed pixel's centre, and
// which seed that is (a matte's distance to its outline, and the object pixel whose colour is
// bled past it). Felzenszwalb & Huttenlocher's method: the nearest seed along each column, then
// along each row the lower envelope of the parabolas those make. The browser runs the same steps
// in the same order in client/web/render/tween/matte_sample.js, so both find the same distances
// and, where two seeds are as near, the same one (tests/golden/warp-vectors.json pins it).
#include <cstdint>
#include <span>
#include <vector>

namespace inkwire {

struct DistanceField {
  std::vector<double> distance;  // +infinity where there is no seed at all
  std::vector<int32_t> nearest;  // y * width + x of the nearest seed, -1 where there is none
};

// `seed`: width * height bytes, nonzero at a seed.
DistanceField distance_to_seeds(std::span<const uint8_t> seed, int width, int height);

}  // namespace inkwire
