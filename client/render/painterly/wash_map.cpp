#include "client/render/painterly/wash_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/luminance.hpp"

namespace inkwire {
namespace {

constexpr int kWetBand = 3;                // pixels: how far inside the outline pigment gathers
constexpr float kColourEdgeLow = 0.05f;    // luminance steps per pixel: a shading slope stays under this...
constexpr float kColourEdgeHigh = 0.18f;   // ...a boundary between colours lies over this

// Running sums over the window, zeros beyond the ends: along each row, then down all columns at
// once (row by row, so memory is read in order; each column's sum is added to as the row-wise
// pass would, so both give the same numbers).
void blur_rows(const std::vector<float>& in, std::vector<float>& out, int width, int height, int radius) {
  const float scale = 1.0f / float(2 * radius + 1);
  for (int y = 0; y < height; ++y) {
    const float* row = &in[size_t(y) * size_t(width)];
    float* to = &out[size_t(y) * size_t(width)];
    double sum = 0.0;
    for (int i = 0; i <= std::min(radius, width - 1); ++i) sum += row[i];
    for (int i = 0; i < width; ++i) {
      to[i] = float(sum) * scale;
      if (i + radius + 1 < width) sum += row[i + radius + 1];
      if (i - radius >= 0) sum -= row[i - radius];
    }
  }
}

void blur_columns(const std::vector<float>& in, std::vector<float>& out, int width, int height, int radius) {
  const float scale = 1.0f / float(2 * radius + 1);
  std::vector<double> sum(size_t(width), 0.0);
  auto row = [&](int y) { return &in[size_t(y) * size_t(width)]; };
  for (int i = 0; i <= std::min(radius, height - 1); ++i)
    for (int x = 0; x < width; ++x) sum[size_t(x)] += row(i)[x];
  for (int y = 0; y < height; ++y) {
    float* to = &out[size_t(y) * size_t(width)];
    for (int x = 0; x < width; ++x) to[x] = float(sum[size_t(x)]) * scale;
    if (y + radius + 1 < height)
      for (int x = 0; x < width; ++x) sum[size_t(x)] += row(y + radius + 1)[x];
    if (y - radius >= 0)
      for (int x = 0; x < width; ++x) sum[size_t(x)] -= row(y - radius)[x];
  }
}

float luminance(const uint8_t* p) { return rec709_luminance<float>(p[0], p[1], p[2]) / 255.0f; }

}  // namespace

void blur_plane(std::vector<float>& plane, int width, int height, int radius) {
  std::vector<float> scratch;
  blur_plane(plane, width, height, radius, scratch);
}

void blur_plane(std::vector<float>& plane, int width, int height, int radius, std::vector<float>& scratch) {
  if (radius < 1 || width < 1 || height < 1) return;
  scratch.resize(plane.size());
  for (int pass = 0; pass < 2; ++pass) {
    blur_rows(plane, scratch, width, height, radius);
    blur_columns(scratch, plane, width, height, radius);
  }
}

const Image& WashMapper::make(const Image& reference, float soft_radius, bool wet_edges) {
  const int w = reference.width, h = reference.height;
  const size_t n = size_t(w) * size_t(h);
  matte_.resize(n);
  for (size_t i = 0; i < n; ++i) matte_[i] = reference.pixels[4 * i + 3] >= 128 ? 1.0f : 0.0f;
  // Two box passes of radius r reach 2r: half the soft radius each.
  soft_ = matte_;
  blur_plane(soft_, w, h, std::max(1, int(std::lround(soft_radius * 0.5f))), scratch_);
  if (out_.width != w || out_.height != h) out_ = Image(w, h);
  // Full paint up to the outline, fading over the soft radius beyond it; no wet pigment yet.
  for (size_t i = 0; i < n; ++i) {
    uint8_t* p = &out_.pixels[4 * i];
    p[0] = uint8_t((matte_[i] > 0.0f ? 1.0f : std::min(2.0f * soft_[i], 1.0f)) * 255.0f + 0.5f);
    p[1] = p[2] = 0;
    p[3] = 255;
  }
  if (!wet_edges) return out_;
  std::vector<float>& near_edge = matte_;  // the matte is not needed any more
  blur_plane(near_edge, w, h, (kWetBand + 1) / 2, scratch_);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (reference.at(x, y)[3] < 128) continue;
      const float band = 1.0f - std::clamp((near_edge[size_t(y) * size_t(w) + size_t(x)] - 0.5f) / 0.45f, 0.0f, 1.0f);
      const uint8_t* left = reference.at(std::max(x - 1, 0), y);
      const uint8_t* right = reference.at(std::min(x + 1, w - 1), y);
      const uint8_t* up = reference.at(x, std::max(y - 1, 0));
      const uint8_t* down = reference.at(x, std::min(y + 1, h - 1));
      // Only between object pixels: the outline is the band's, not the colours'.
      float step = 0.0f;
      if (left[3] >= 128 && right[3] >= 128 && up[3] >= 128 && down[3] >= 128)
        step = 0.5f * std::hypot(luminance(right) - luminance(left), luminance(down) - luminance(up));
      const float colour_edge = std::clamp((step - kColourEdgeLow) / (kColourEdgeHigh - kColourEdgeLow), 0.0f, 1.0f);
      out_.at(x, y)[1] = uint8_t(std::max(band, 0.8f * colour_edge) * 255.0f + 0.5f);
    }
  return out_;
}

}  // namespace inkwire
