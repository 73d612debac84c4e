#pragma once
// Tileable value noise for procedural textures (paper, pencil and charcoal grain, brushes):
// lattice values wrap every `period` cells, so a texture made from it tiles seamlessly.
#include <cmath>
#include <cstdint>
#include <vector>

namespace inkwire {

class TileableNoise {
 public:
  TileableNoise(int period, uint32_t seed) : period_(period), values_(size_t(period) * period) {
    uint32_t state = seed * 747796405u + 2891336453u;
    for (float& v : values_) {
      state = state * 1664525u + 1013904223u;
      v = float(state >> 8) / float(1u << 24);
    }
  }
  // Value in 0..1 at (u, v) measured in cells, smoothly (cubic) interpolated.
  float at(float u, float v) const {
    const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
    const float fx = u - float(x0), fy = v - float(y0);
    const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const float a = lattice(x0, y0), b = lattice(x0 + 1, y0), c = lattice(x0, y0 + 1), d = lattice(x0 + 1, y0 + 1);
    return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy;
  }

 private:
  float lattice(int x, int y) const {
    x = ((x % period_) + period_) % period_;
    y = ((y % period_) + period_) % period_;
    return values_[size_t(y) * size_t(period_) + size_t(x)];
  }
  int period_;
  std::vector<float> values_;
};

}  // namespace inkwire
