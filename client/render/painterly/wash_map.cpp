#include "client/render/painterly/wash_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace inkwire {
namespace {

constexpr int kWetBand = 3;                // pixels: how far inside the outline pigment gathers
constexpr float kColourEdgeLow = 0.05f;    // luminance steps per pixel: a shading slope stays under this...
constexpr float kColourEdgeHigh = 0.18f;   // ...a boundary between colours lies over this

void blur_line(const float* in, float* out, int n, int stride, int radius) {
  // Running sum over the window, zeros beyond the ends.
  double sum = 0.0;
  for (int i = 0; i <= std::min(radius, n - 1); ++i) sum += in[i * stride];
  const float scale = 1.0f / float(2 * radius + 1);
  for (int i = 0; i < n; ++i) {
    out[i * stride] = float(sum) * scale;
    if (i + radius + 1 < n) sum += in[(i + radius + 1) * stride];
    if (i - radius >= 0) sum -= in[(i - radius) * stride];
  }
}

float luminance(const uint8_t* p) { return (0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]) / 255.0f; }

}  // namespace

void blur_plane(std::vector<float>& plane, int width, int height, int radius) {
  if (radius < 1 || width < 1 || height < 1) return;
  std::vector<float> scratch(plane.size());
  for (int pass = 0; pass < 2; ++pass) {
    for (int y = 0; y < height; ++y) blur_line(&plane[size_t(y) * width], &scratch[size_t(y) * width], width, 1, radius);
    for (int x = 0; x < width; ++x) blur_line(&scratch[size_t(x)], &plane[size_t(x)], height, width, radius);
  }
}

Image wash_map(const Image& reference, float soft_radius) {
  const int w = reference.width, h = reference.height;
  std::vector<float> matte(size_t(w) * h), soft, near_edge;
  for (size_t i = 0; i < matte.size(); ++i) matte[i] = reference.pixels[4 * i + 3] >= 128 ? 1.0f : 0.0f;
  soft = near_edge = matte;
  // Two box passes of radius r reach 2r: half the soft radius each.
  blur_plane(soft, w, h, std::max(1, int(std::lround(soft_radius * 0.5f))));
  blur_plane(near_edge, w, h, (kWetBand + 1) / 2);
  Image out(w, h, {0, 0, 0, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      // Full paint up to the outline, fading over the soft radius beyond it.
      const float paint = matte[i] > 0.0f ? 1.0f : std::clamp(2.0f * soft[i], 0.0f, 1.0f);
      float wet = 0.0f;
      if (matte[i] > 0.0f) {
        const float band = 1.0f - std::clamp((near_edge[i] - 0.5f) / 0.45f, 0.0f, 1.0f);
        const uint8_t* left = reference.at(std::max(x - 1, 0), y);
        const uint8_t* right = reference.at(std::min(x + 1, w - 1), y);
        const uint8_t* up = reference.at(x, std::max(y - 1, 0));
        const uint8_t* down = reference.at(x, std::min(y + 1, h - 1));
        // Only between object pixels: the outline is the band's, not the colours'.
        float step = 0.0f;
        if (left[3] >= 128 && right[3] >= 128 && up[3] >= 128 && down[3] >= 128)
          step = 0.5f * std::hypot(luminance(right) - luminance(left), luminance(down) - luminance(up));
        const float colour_edge = std::clamp((step - kColourEdgeLow) / (kColourEdgeHigh - kColourEdgeLow), 0.0f, 1.0f);
        wet = std::max(band, 0.8f * colour_edge);
      }
      uint8_t* p = out.at(x, y);
      p[0] = uint8_t(paint * 255.0f + 0.5f);
      p[1] = uint8_t(wet * 255.0f + 0.5f);
    }
  return out;
}

}  // namespace inkwire
