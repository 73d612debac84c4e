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

// Value noise in 0..1 over space (no period): hashed lattice values, smoothly (cubic)
// interpolated between the 8 corners of the cell around (x, y, z), measured in cells. For
// properties that must agree wherever two things meet at one point (a stroke's pressure where
// two edges share a vertex).
inline float value_noise(float x, float y, float z, uint32_t seed) {
  auto lattice = [seed](int i, int j, int k) {
    uint32_t h = seed * 0x9E3779B9u ^ uint32_t(i) * 0x85EBCA6Bu ^ uint32_t(j) * 0xC2B2AE35u ^ uint32_t(k) * 0x27D4EB2Fu;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return float(h >> 8) / float(1u << 24);
  };
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y)), z0 = int(std::floor(z));
  auto smooth = [](float t) { return t * t * (3 - 2 * t); };
  const float sx = smooth(x - float(x0)), sy = smooth(y - float(y0)), sz = smooth(z - float(z0));
  auto mix = [](float a, float b, float t) { return a + (b - a) * t; };
  float layer[2];
  for (int k = 0; k < 2; ++k)
    layer[k] = mix(mix(lattice(x0, y0, z0 + k), lattice(x0 + 1, y0, z0 + k), sx), mix(lattice(x0, y0 + 1, z0 + k), lattice(x0 + 1, y0 + 1, z0 + k), sx), sy);
  return mix(layer[0], layer[1], sz);
}

}  // namespace inkwire
