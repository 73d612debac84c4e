#include "common/distance_field.hpp"

#include <cmath>
#include <limits>

#include "common/error.hpp"

namespace inkwire {

DistanceField distance_to_seeds(std::span<const uint8_t> seed, int width, int height) {
  if (width <= 0 || height <= 0 || seed.size() != size_t(width) * size_t(height))
    throw Error("distance_to_seeds(): " + std::to_string(seed.size()) + " seed bytes for " + std::to_string(width) + "x" + std::to_string(height));
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const size_t w = size_t(width);
  // Each pixel's nearest seed in its column, by row (-1: none); of two as near, the one above.
  std::vector<int32_t> column_seed(seed.size(), -1);
  for (size_t x = 0; x < w; ++x) {
    int32_t last = -1;
    for (int y = 0; y < height; ++y) {
      if (seed[size_t(y) * w + x]) last = y;
      column_seed[size_t(y) * w + x] = last;
    }
    last = -1;
    for (int y = height - 1; y >= 0; --y) {
      const size_t i = size_t(y) * w + x;
      if (seed[i]) last = y;
      if (last >= 0 && (column_seed[i] < 0 || last - y < y - column_seed[i])) column_seed[i] = last;
    }
  }
  DistanceField out{std::vector<double>(seed.size(), kInfinity), std::vector<int32_t>(seed.size(), -1)};
  // Along each row, pixel q's column seed lies f(q) squared away: the distance at x is the lowest
  // of the parabolas (x - q)^2 + f(q). `parabola` holds the envelope's, `from` where each begins.
  std::vector<int> parabola(w);
  std::vector<double> from(w + 1), f(w);
  for (int y = 0; y < height; ++y) {
    const int32_t* row_seed = &column_seed[size_t(y) * w];
    int k = -1;
    for (int q = 0; q < width; ++q) {
      if (row_seed[q] < 0) continue;
      f[size_t(q)] = double(row_seed[q] - y) * double(row_seed[q] - y);
      double s = -kInfinity;
      while (k >= 0) {
        const int p = parabola[size_t(k)];
        s = ((f[size_t(q)] + double(q) * double(q)) - (f[size_t(p)] + double(p) * double(p))) / (2.0 * double(q) - 2.0 * double(p));
        if (s > from[size_t(k)]) break;
        --k;
      }
      ++k;
      parabola[size_t(k)] = q;
      from[size_t(k)] = k == 0 ? -kInfinity : s;
      from[size_t(k) + 1] = kInfinity;
    }
    if (k < 0) continue;  // no seed in any column crossing this row: no seed at all
    size_t j = 0;
    for (int x = 0; x < width; ++x) {
      while (from[j + 1] < double(x)) ++j;
      const int q = parabola[j];
      const size_t i = size_t(y) * w + size_t(x);
      out.distance[i] = std::sqrt(double(x - q) * double(x - q) + f[size_t(q)]);
      out.nearest[i] = row_seed[q] * width + q;
    }
  }
  return out;
}

}  // namespace inkwire
