#include "client/render/face/comic_photo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "common/luminance.hpp"
#include "common/percentile.hpp"

// Plain C++ on purpose: the browser's module draws call faces with this same code (SPEC F16), and
// OpenCV is not there. The steps are the classic ones (bilateral smoothing at half size, tone
// bands, Canny's edges), each small enough to read here. Bit for bit the same in both: only
// +-*/ on floats (which IEEE rounds alike everywhere) and weights from exp() rounded to 1/65536,
// since the C libraries' exp() may differ in a last bit and a band or an edge would flip.
namespace inkwire {
namespace {

float rounded_weight(float w) { return std::round(w * 65536.0f) / 65536.0f; }

struct Rgb {
  float r = 0, g = 0, b = 0;
};

// A plane of RGB floats (0..255), row 0 at the top.
struct Plane {
  int width = 0, height = 0;
  std::vector<Rgb> px;
  Rgb& at(int x, int y) { return px[size_t(y) * size_t(width) + size_t(x)]; }
  const Rgb& at(int x, int y) const { return px[size_t(y) * size_t(width) + size_t(x)]; }
};

Plane half_size(const Image& image) {
  Plane half{std::max(1, image.width / 2), std::max(1, image.height / 2), {}};
  half.px.resize(size_t(half.width) * size_t(half.height));
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x) {
      Rgb sum;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const uint8_t* p = image.at(std::min(2 * x + dx, image.width - 1), std::min(2 * y + dy, image.height - 1));
          sum.r += p[0], sum.g += p[1], sum.b += p[2];
        }
      half.at(x, y) = {sum.r / 4, sum.g / 4, sum.b / 4};
    }
  return half;
}

// Edge-preserving smoothing: each pixel the mean of its 7x7 neighbours weighted by distance
// (sigma 5 px) and by colour difference (sigma 40 levels), as OpenCV's bilateralFilter weighs them.
Plane bilateral(const Plane& in) {
  constexpr int kRadius = 3;
  constexpr float kSigmaColour = 40, kSigmaSpace = 5;
  std::array<float, (2 * kRadius + 1) * (2 * kRadius + 1)> space{};
  for (int dy = -kRadius; dy <= kRadius; ++dy)
    for (int dx = -kRadius; dx <= kRadius; ++dx)
      space[size_t((dy + kRadius) * (2 * kRadius + 1) + dx + kRadius)] =
          dx * dx + dy * dy > kRadius * kRadius ? 0.0f : rounded_weight(std::exp(-float(dx * dx + dy * dy) / (2 * kSigmaSpace * kSigmaSpace)));
  std::array<float, 3 * 256> colour{};  // by the sum of absolute channel differences, as OpenCV's
  for (size_t d = 0; d < colour.size(); ++d) colour[d] = rounded_weight(std::exp(-float(d * d) / (2 * kSigmaColour * kSigmaColour)));
  Plane out = in;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const Rgb c = in.at(x, y);
      Rgb sum;
      float weights = 0;
      for (int dy = -kRadius; dy <= kRadius; ++dy)
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
          const float s = space[size_t((dy + kRadius) * (2 * kRadius + 1) + dx + kRadius)];
          if (s == 0) continue;
          const Rgb& n = in.at(std::clamp(x + dx, 0, in.width - 1), std::clamp(y + dy, 0, in.height - 1));
          const int d = int(std::abs(n.r - c.r) + std::abs(n.g - c.g) + std::abs(n.b - c.b));
          const float w = s * colour[size_t(std::min(d, int(colour.size()) - 1))];
          sum.r += w * n.r, sum.g += w * n.g, sum.b += w * n.b;
          weights += w;
        }
      out.at(x, y) = {sum.r / weights, sum.g / weights, sum.b / weights};
    }
  return out;
}

Rgb bilinear(const Plane& p, float x, float y) {
  x = std::clamp(x, 0.0f, float(p.width - 1)), y = std::clamp(y, 0.0f, float(p.height - 1));
  const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, p.width - 1), y1 = std::min(y0 + 1, p.height - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  const auto mix = [](const Rgb& a, const Rgb& b, float t) { return Rgb{a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; };
  return mix(mix(p.at(x0, y0), p.at(x1, y0), fx), mix(p.at(x0, y1), p.at(x1, y1), fx), fy);
}

float luma(float r, float g, float b) { return rec601_luma(r, g, b); }

// Canny's edges of a grey picture: a 5x5 median against the photo's grain, Sobel gradients,
// thinned to their ridge, kept above `high` or joined to such an edge above `low`.
std::vector<uint8_t> canny_edges(std::vector<float> grey, int width, int height, float low, float high) {
  const auto index = [width](int x, int y) { return size_t(y) * size_t(width) + size_t(x); };
  {
    std::vector<float> median(grey.size());
    std::array<float, 25> window{};
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        size_t n = 0;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) window[n++] = grey[index(std::clamp(x + dx, 0, width - 1), std::clamp(y + dy, 0, height - 1))];
        median[index(x, y)] = *median_in_place(std::span<float>(window));  // rank 12 of the 25
      }
    grey = std::move(median);
  }
  std::vector<float> gx(grey.size()), gy(grey.size()), magnitude(grey.size());
  const auto g = [&](int x, int y) { return grey[index(std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1))]; };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float sx = (g(x + 1, y - 1) + 2 * g(x + 1, y) + g(x + 1, y + 1)) - (g(x - 1, y - 1) + 2 * g(x - 1, y) + g(x - 1, y + 1));
      const float sy = (g(x - 1, y + 1) + 2 * g(x, y + 1) + g(x + 1, y + 1)) - (g(x - 1, y - 1) + 2 * g(x, y - 1) + g(x + 1, y - 1));
      gx[index(x, y)] = sx, gy[index(x, y)] = sy;
      magnitude[index(x, y)] = std::abs(sx) + std::abs(sy);  // OpenCV's L1 gradient, which its thresholds are for
    }
  // 0: no edge, 1: weak, 2: strong.
  std::vector<uint8_t> kind(grey.size(), 0);
  for (int y = 1; y + 1 < height; ++y)
    for (int x = 1; x + 1 < width; ++x) {
      const float m = magnitude[index(x, y)];
      if (m <= low) continue;
      // Across the edge: compare with the two neighbours along the gradient (in four directions).
      const float ax = std::abs(gx[index(x, y)]), ay = std::abs(gy[index(x, y)]);
      int dx = 0, dy = 0;
      if (ay <= ax * 0.4142f) dx = 1;
      else if (ay >= ax * 2.4142f) dy = 1;
      else dx = 1, dy = (gx[index(x, y)] > 0) == (gy[index(x, y)] > 0) ? 1 : -1;
      if (m < magnitude[index(x + dx, y + dy)] || m <= magnitude[index(x - dx, y - dy)]) continue;
      kind[index(x, y)] = m > high ? 2 : 1;
    }
  std::vector<uint8_t> edges(grey.size(), 0);
  std::vector<std::pair<int, int>> stack;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (kind[index(x, y)] == 2 && !edges[index(x, y)]) {
        stack.push_back({x, y});
        edges[index(x, y)] = 255;
        while (!stack.empty()) {
          const auto [cx, cy] = stack.back();
          stack.pop_back();
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int nx = cx + dx, ny = cy + dy;
              if (nx < 0 || ny < 0 || nx >= width || ny >= height || edges[index(nx, ny)] || !kind[index(nx, ny)]) continue;
              edges[index(nx, ny)] = 255;
              stack.push_back({nx, ny});
            }
        }
      }
  return edges;
}

}  // namespace

void comic_photo(Image& image, int bands) {
  if (image.width < 8 || image.height < 8) return;
  bands = std::clamp(bands, 2, 8);
  // Flat areas, sharp borders: two small bilateral passes on a half-size copy, scaled back.
  const Plane smooth = bilateral(bilateral(half_size(image)));
  const float sx = float(smooth.width) / float(image.width), sy = float(smooth.height) / float(image.height);
  std::vector<float> grey(size_t(image.width) * size_t(image.height));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      grey[size_t(y) * size_t(image.width) + size_t(x)] = luma(p[0], p[1], p[2]);
    }
  // Ink: the strong edges of the grey photo, a little thickened (each edge pixel also inks the
  // pixel right of and below it).
  const std::vector<uint8_t> edges = canny_edges(std::move(grey), image.width, image.height, 40, 110);
  const auto edge = [&](int x, int y) { return x >= 0 && y >= 0 && edges[size_t(y) * size_t(image.width) + size_t(x)] != 0; };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      uint8_t* out = image.at(x, y);
      if (edge(x, y) || edge(x - 1, y) || edge(x, y - 1) || edge(x - 1, y - 1)) {
        out[0] = 25, out[1] = 20, out[2] = 20;
        continue;
      }
      // Tone bands on the luminance, the darkest band a quarter darker still; colour kept.
      const Rgb c = bilinear(smooth, (float(x) + 0.5f) * sx - 0.5f, (float(y) + 0.5f) * sy - 0.5f);
      const float l = luma(c.r, c.g, c.b);
      const int band = std::min(bands - 1, int(l * float(bands) / 256.0f));
      float banded = (float(band) + 0.5f) * 255.0f / float(bands);
      if (band == 0) banded *= 0.76f;
      const float gain = l > 1 ? banded / l : 0;
      const auto channel = [&](float v) { return uint8_t(std::clamp(std::lround(l > 1 ? v * gain : banded), 0L, 255L)); };
      out[0] = channel(c.r), out[1] = channel(c.g), out[2] = channel(c.b);
    }
}

}  // namespace inkwire
