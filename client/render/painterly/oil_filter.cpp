#include "client/render/painterly/oil_filter.hpp"

#include <algorithm>
#include <vector>

#include "common/error.hpp"

namespace inkwire {

Image oil_filter(const Image& image, int radius, int levels) {
  if (radius < 1 || radius > 64) throw Error("oil filter radius must be 1..64");
  if (levels < 2 || levels > 256) throw Error("oil filter levels must be 2..256");
  Image out = image;
  const int w = image.width, h = image.height;
  std::vector<int> bin_of(size_t(w) * h, -1);  // -1: not an object pixel
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = image.at(x, y);
      if (p[3] >= 128) bin_of[size_t(y) * w + x] = (p[0] + p[1] + p[2]) * levels / (3 * 256);
    }
  std::vector<int> count(static_cast<size_t>(levels));
  std::vector<int> sum(static_cast<size_t>(levels) * 3);
  auto column = [&](int x, int y0, int y1, int sign) {
    if (x < 0 || x >= w) return;
    for (int y = std::max(y0, 0); y <= std::min(y1, h - 1); ++y) {
      const int b = bin_of[size_t(y) * w + x];
      if (b < 0) continue;
      const uint8_t* p = image.at(x, y);
      count[size_t(b)] += sign;
      for (int c = 0; c < 3; ++c) sum[size_t(b) * 3 + c] += sign * p[c];
    }
  };
  for (int y = 0; y < h; ++y) {
    std::fill(count.begin(), count.end(), 0);
    std::fill(sum.begin(), sum.end(), 0);
    for (int x = -radius; x <= radius; ++x) column(x, y - radius, y + radius, +1);
    for (int x = 0; x < w; ++x) {
      if (x > 0) {
        column(x - radius - 1, y - radius, y + radius, -1);
        column(x + radius, y - radius, y + radius, +1);
      }
      if (bin_of[size_t(y) * w + x] < 0) continue;
      const size_t best = size_t(std::max_element(count.begin(), count.end()) - count.begin());
      uint8_t* o = out.at(x, y);
      for (int c = 0; c < 3; ++c) o[c] = uint8_t(sum[best * 3 + c] / count[best]);
    }
  }
  return out;
}

}  // namespace inkwire
