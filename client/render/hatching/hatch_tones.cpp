#include "client/render/hatching/hatch_tones.hpp"

#include <algorithm>
#include <cmath>

#include "client/render/sketch/perturb.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

struct HatchStroke {
  float x, y;        // start, in texels
  float length;      // texels
  float angle;       // radians
  float weight;      // ink opacity
};

// Draws a soft, slightly tapered line into `img` (alpha = ink, max-combined), wrapping at
// the edges so the tile stays seamless.
void draw_stroke(Image& img, const HatchStroke& s) {
  const int size = img.width;
  const float dx = std::cos(s.angle), dy = std::sin(s.angle);
  const int steps = int(s.length * 3.0f);
  for (int i = 0; i <= steps; ++i) {
    const float t = float(i) / float(std::max(steps, 1));
    const float taper = std::min(1.0f, std::min(t, 1.0f - t) * 6.0f + 0.3f);
    const float cx = s.x + dx * s.length * t, cy = s.y + dy * s.length * t;
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const int px = int(std::floor(cx)) + ox, py = int(std::floor(cy)) + oy;
        const float d = std::hypot(float(px) + 0.5f - cx, float(py) + 0.5f - cy);
        const float a = std::clamp(1.0f - d / 1.1f, 0.0f, 1.0f) * s.weight * taper;
        uint8_t* p = img.at(((px % size) + size) % size, ((py % size) + size) % size);
        p[3] = std::max(p[3], uint8_t(a * 255.0f));
      }
  }
}

}  // namespace

HatchTones make_hatch_tones(int layers, int size, uint32_t seed) {
  if (layers < 2 || layers > 64 || size < 16 || size > 1024 || (size & (size - 1)))
    throw Error("hatch tones: 2..64 layers of a power-of-two size 16..1024");
  // One ordered list of strokes; layer k holds its first n_k. Early strokes run one way,
  // later ones cross them, as an artist darkens a tone.
  StrokeRandom random(stroke_seed(seed, 5));
  std::vector<HatchStroke> strokes;
  const int total = size * size / 20;
  for (int i = 0; i < total; ++i) {
    const bool cross = i >= total / 2;
    const float angle = (cross ? -0.6f : 0.75f) + random.uniform(-0.08f, 0.08f);
    strokes.push_back({random.uniform(0.0f, float(size)), random.uniform(0.0f, float(size)),
                       random.uniform(0.3f, 0.6f) * float(size), angle, random.uniform(0.65f, 1.0f)});
  }
  HatchTones tones;
  for (int k = 0; k < layers; ++k) {
    // Strokes grow roughly with the square of the tone, so tones look evenly spaced.
    const float tone = float(k) / float(layers - 1);
    const int n = int(std::round(float(total) * tone * tone));
    Image img(size, size, {40, 40, 46, 0});  // graphite colour, no ink yet
    for (int i = 0; i < n; ++i) draw_stroke(img, strokes[size_t(i)]);
    tones.layers.push_back(std::move(img));
    tones.strokes_in_layer.push_back(n);
  }
  return tones;
}

double ink_coverage(const Image& layer) {
  size_t inked = 0;
  for (size_t i = 3; i < layer.pixels.size(); i += 4) inked += layer.pixels[i] > 127;
  return double(inked) / double(layer.width * layer.height);
}

}  // namespace inkwire
