#include "client/render/painterly/brush_shapes.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "common/noise.hpp"
#include "common/random.hpp"
#include "common/shaping.hpp"

namespace inkwire {

namespace {

const std::vector<std::string> kNames = {"dot", "stroke", "blotch", "spatter", "wash"};

void put(Image& image, int x, int y, float shade, float alpha) {
  uint8_t* p = image.at(x, y);
  const uint8_t s = uint8_t(std::clamp(shade, 0.0f, 1.0f) * 255.0f + 0.5f);
  p[0] = p[1] = p[2] = s;
  p[3] = uint8_t(std::clamp(alpha, 0.0f, 1.0f) * 255.0f + 0.5f);
}

// Bristles dragged left to right: each bristle is a thin line at its own height whose paint
// runs out at its own length; the stroke narrows a little toward both ends.
Image stroke(uint32_t seed) {
  const int n = kBrushTextureSize;
  Image image(n, n);
  Random random(seed);
  constexpr int kBristles = 14;
  float height[kBristles], reach[kBristles], strength[kBristles];
  for (int b = 0; b < kBristles; ++b) {
    height[b] = (float(b) + 0.5f) / float(kBristles) + random.uniform(-0.02f, 0.02f);
    reach[b] = random.uniform(0.6f, 0.98f);
    strength[b] = random.uniform(0.55f, 1.0f);
  }
  const TileableNoise grain(16, seed * 7 + 3);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float u = (float(x) + 0.5f) / float(n), v = (float(y) + 0.5f) / float(n);
      const float half_width = 0.46f * (0.75f + 0.25f * std::sin(3.14159f * std::clamp(u * 1.1f, 0.0f, 1.0f)));
      const float across = std::abs(v - 0.5f);
      const float body = 1.0f - smoothstep(half_width - 0.06f, half_width, across);
      float bristle = 0.0f, shade = 0.0f;
      for (int b = 0; b < kBristles; ++b) {
        const float d = std::abs(v - height[b]) * float(kBristles);
        const float line = 1.0f - smoothstep(0.35f, 0.75f, d);
        const float dry = 1.0f - smoothstep(reach[b] - 0.25f, reach[b], u);  // paint runs out
        bristle = std::max(bristle, line * dry * strength[b]);
        shade = std::max(shade, line * strength[b]);
      }
      const float start = smoothstep(0.0f, 0.08f, u);  // rounded loaded start
      const float fill = 0.55f + 0.45f * (1.0f - u);   // the paint thins along the stroke
      const float alpha = body * start * std::clamp(0.45f * fill + 0.75f * bristle, 0.0f, 1.0f);
      put(image, x, y, 0.8f + 0.2f * shade * grain.at(u * 16, v * 4), alpha);
    }
  return image;
}

// A round dab of a loaded brush: dense middle, bristle-ragged rim.
Image dot(uint32_t seed) {
  const int n = kBrushTextureSize;
  Image image(n, n);
  const TileableNoise rim(12, seed * 11 + 5), grain(16, seed * 13 + 1);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float dx = (float(x) + 0.5f) / float(n) - 0.5f, dy = (float(y) + 0.5f) / float(n) - 0.5f;
      const float r = std::sqrt(dx * dx + dy * dy);
      const float angle = std::atan2(dy, dx) / 6.28318f + 0.5f;
      const float edge = 0.40f + 0.08f * rim.at(angle * 12, 0.5f);
      const float alpha = 1.0f - smoothstep(edge - 0.08f, edge, r);
      put(image, x, y, 0.82f + 0.18f * grain.at(float(x) / 4, float(y) / 4), alpha * (0.85f + 0.15f * (1 - r * 2)));
    }
  return image;
}

// An irregular pool of thinner paint, darker where it dried at the rim (watercolour edge).
Image blotch(uint32_t seed) {
  const int n = kBrushTextureSize;
  Image image(n, n);
  const TileableNoise shape(8, seed * 17 + 9), grain(16, seed * 19 + 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float dx = (float(x) + 0.5f) / float(n) - 0.5f, dy = (float(y) + 0.5f) / float(n) - 0.5f;
      const float r = std::sqrt(dx * dx + dy * dy);
      const float angle = std::atan2(dy, dx) / 6.28318f + 0.5f;
      const float edge = 0.30f + 0.16f * shape.at(angle * 8, 2.0f);
      const float inside = 1.0f - smoothstep(edge - 0.05f, edge, r);
      const float rim = smoothstep(edge - 0.12f, edge - 0.03f, r);  // pigment gathers at the rim
      const float alpha = inside * (0.6f + 0.4f * rim) * (0.85f + 0.15f * grain.at(float(x) / 4, float(y) / 4));
      put(image, x, y, 1.0f - 0.2f * rim, alpha);
    }
  return image;
}

// Droplets flicked from a brush: many small round spots, denser and larger near the middle.
Image spatter(uint32_t seed) {
  const int n = kBrushTextureSize;
  Image image(n, n);
  Random random(seed * 23 + 7);
  std::vector<float> alpha(size_t(n) * n, 0.0f);
  for (int drop = 0; drop < 26; ++drop) {
    const float spread = random.uniform(0.0f, 0.36f), angle = random.uniform(0, 6.28318f);
    const float cx = 0.5f + spread * std::cos(angle), cy = 0.5f + spread * std::sin(angle);
    const float radius = (0.075f - 0.12f * spread) * random.uniform(0.5f, 1.2f) + 0.02f;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float dx = (float(x) + 0.5f) / float(n) - cx, dy = (float(y) + 0.5f) / float(n) - cy;
        const float a = 1.0f - smoothstep(radius * 0.7f, radius, std::sqrt(dx * dx + dy * dy));
        alpha[size_t(y) * n + x] = std::max(alpha[size_t(y) * n + x], a);
      }
  }
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) put(image, x, y, 0.92f, alpha[size_t(y) * n + x]);
  return image;
}

// A wet wash: a broad, soft-edged pool with an irregular edge and no rim of its own (the rim a
// wash leaves is where it ends as a whole, which the painter adds: wet edges), its pigment a
// little uneven where the water carried it.
Image wash(uint32_t seed) {
  const int n = kBrushTextureSize;
  Image image(n, n);
  const TileableNoise shape(6, seed * 29 + 3), flow(8, seed * 31 + 5);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float dx = (float(x) + 0.5f) / float(n) - 0.5f, dy = (float(y) + 0.5f) / float(n) - 0.5f;
      const float r = std::sqrt(dx * dx + dy * dy);
      const float angle = std::atan2(dy, dx) / 6.28318f + 0.5f;
      const float edge = 0.36f + 0.1f * (shape.at(angle * 6, 1.5f) - 0.5f);
      const float alpha = (1.0f - smoothstep(edge - 0.2f, edge, r)) * (0.8f + 0.2f * flow.at(float(x) / 8, float(y) / 8));
      put(image, x, y, 1.0f, alpha);
    }
  return image;
}

}  // namespace

BrushShape brush_shape(const std::string& name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return BrushShape(i);
  throw Error("unknown brush shape '" + name + "' (known: dot, stroke, blotch, spatter, wash)");
}

Image make_brush_texture(BrushShape shape, uint32_t seed) {
  switch (shape) {
    case BrushShape::Dot: return dot(seed);
    case BrushShape::Stroke: return stroke(seed);
    case BrushShape::Blotch: return blotch(seed);
    case BrushShape::Spatter: return spatter(seed);
    case BrushShape::Wash: return wash(seed);
  }
  throw Error("make_brush_texture(): bad shape");
}

std::vector<Image> make_brush_textures() {
  std::vector<Image> all;
  for (size_t i = 0; i < kNames.size(); ++i) all.push_back(make_brush_texture(BrushShape(i)));
  return all;
}

float shape_aspect(BrushShape shape, float stroke_aspect) { return shape == BrushShape::Stroke ? stroke_aspect : 1.0f; }

}  // namespace inkwire
