#pragma once
// Synthetic images for tests: a scene with distinct features everywhere (discs of random colours
// and sizes over a gradient), which landmark finding and tweening can work on (regular patterns
// repeat, and landmarks rightly refuse them), and a camera panning over it.
#include <algorithm>

#include "common/image.hpp"
#include "common/random.hpp"

namespace inkwire::test {

inline Image random_discs(int w, int h, uint64_t seed) {
  Image image(w, h);
  Random random(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = image.at(x, y);
      p[0] = uint8_t(60 + 120 * x / w), p[1] = uint8_t(80 + 100 * y / h), p[2] = 120, p[3] = 255;
    }
  for (int i = 0; i < w * h / 300; ++i) {
    const float cx = random.uniform(0.0f, float(w)), cy = random.uniform(0.0f, float(h)), r = random.uniform(3.0f, 10.0f);
    const uint8_t c[4] = {uint8_t(random.uniform(0.0f, 255.0f)), uint8_t(random.uniform(0.0f, 255.0f)), uint8_t(random.uniform(0.0f, 255.0f)), 255};
    for (int y = std::max(0, int(cy - r)); y < std::min(h, int(cy + r) + 1); ++y)
      for (int x = std::max(0, int(cx - r)); x < std::min(w, int(cx + r) + 1); ++x)
        if ((float(x) - cx) * (float(x) - cx) + (float(y) - cy) * (float(y) - cy) < r * r) std::copy_n(c, 4, image.at(x, y));
  }
  return image;
}

// The `width`-pixel window of `scene` that starts `shift` pixels in.
inline Image panned(const Image& scene, int shift, int width) { return cropped(scene, shift, 0, width, scene.height); }

}  // namespace inkwire::test
