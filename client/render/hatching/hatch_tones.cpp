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

// Draws a soft, slightly tapered line of radius `pen` texels into `img` (alpha = ink,
// max-combined), wrapping at the edges so the tile stays seamless.
void draw_stroke(Image& img, const HatchStroke& s, float pen) {
  const int size = img.width;
  const int reach = int(std::ceil(pen + 0.5f));
  const float dx = std::cos(s.angle), dy = std::sin(s.angle);
  const int steps = int(s.length * 3.0f);
  for (int i = 0; i <= steps; ++i) {
    const float t = float(i) / float(std::max(steps, 1));
    const float taper = std::min(1.0f, std::min(t, 1.0f - t) * 6.0f + 0.3f);
    const float cx = s.x + dx * s.length * t, cy = s.y + dy * s.length * t;
    for (int oy = -reach; oy <= reach; ++oy)
      for (int ox = -reach; ox <= reach; ++ox) {
        const int px = int(std::floor(cx)) + ox, py = int(std::floor(cy)) + oy;
        const float d = std::hypot(float(px) + 0.5f - cx, float(py) + 0.5f - cy);
        const float a = std::clamp(1.0f - d / pen, 0.0f, 1.0f) * s.weight * taper;
        uint8_t* p = img.at(((px % size) + size) % size, ((py % size) + size) % size);
        p[3] = std::max(p[3], uint8_t(a * 255.0f));
      }
  }
}

}  // namespace

HatchTones make_hatch_tones(int layers, int size, uint32_t seed, float cross_tone) {
  if (layers < 2 || layers > 64 || size < 16 || size > 1024) throw Error("hatch tones: 2..64 layers of a size 16..1024");
  if (!(cross_tone >= 0.0f && cross_tone <= 1.0f)) throw Error("hatch tones: the cross-hatching tone must be within 0..1");
  // Two ordered lists of strokes, one per direction; layer k holds the first few of each. The
  // strokes are laid out in the tile, not in texels: any size draws the same tile, sharper or
  // coarser.
  StrokeRandom random(stroke_seed(seed, 5));
  constexpr int kDesignSize = 128;  // the size the stroke count and pen were chosen at
  const int per_direction = kDesignSize * kDesignSize / 40;
  const float pen = 1.1f * float(size) / float(kDesignSize);
  std::vector<HatchStroke> along, across;
  for (int i = 0; i < 2 * per_direction; ++i) {
    const bool cross = i % 2 == 1;
    const float angle = (cross ? kCrossStrokeAngle : kHatchStrokeAngle) + random.uniform(-0.08f, 0.08f);
    (cross ? across : along)
        .push_back({random.uniform(0.0f, float(size)), random.uniform(0.0f, float(size)), random.uniform(0.3f, 0.6f) * float(size),
                    angle, random.uniform(0.65f, 1.0f)});
  }
  // The first direction fills up to the cross-hatching tone, its strokes growing with the square
  // of the tone so light tones look evenly spaced; the second crosses it from there to the
  // darkest, growing linearly, so a crossing shows as soon as the tone passes the threshold.
  // (No cross-hatching: one direction over the whole range.)
  const bool crosses = cross_tone < 1.0f;
  auto share = [](float tone, float from, float to) { return std::clamp((tone - from) / std::max(to - from, 1e-6f), 0.0f, 1.0f); };
  HatchTones tones;
  int drawn_along = 0, drawn_across = 0;
  for (int k = 0; k < layers; ++k) {
    const float tone = float(k) / float(layers - 1);
    const float first = share(tone, 0.0f, crosses ? cross_tone : 1.0f);
    const int n_along = int(std::round(float(per_direction) * first * first));
    const int n_across = crosses && tone > cross_tone ? int(std::round(float(per_direction) * share(tone, cross_tone, 1.0f))) : 0;
    // Each layer is the one before plus its new strokes (ink combines by max: order is free).
    Image img = k == 0 ? Image(size, size, {40, 40, 46, 0}) : tones.layers.back();  // graphite, no ink yet
    for (; drawn_along < n_along; ++drawn_along) draw_stroke(img, along[size_t(drawn_along)], pen);
    for (; drawn_across < n_across; ++drawn_across) draw_stroke(img, across[size_t(drawn_across)], pen);
    tones.layers.push_back(std::move(img));
    tones.strokes_in_layer.push_back(n_along + n_across);
    tones.crossing_in_layer.push_back(n_across);
  }
  return tones;
}

namespace {

// A texel's ink against tone as two steps: `first` up to tone t1, `second` from t2 on.
struct TwoSteps {
  int k1 = 0, k2 = 0;  // layers where the steps happen
  float first = 0.0f, second = 0.0f;
};

// The two steps closest (least squares) to a texel's ink over the layers, which only grows.
TwoSteps fit_two_steps(const std::vector<float>& ink) {
  const int n = int(ink.size());
  std::vector<double> sum(size_t(n) + 1, 0.0), squares(size_t(n) + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    sum[size_t(k) + 1] = sum[size_t(k)] + ink[size_t(k)];
    squares[size_t(k) + 1] = squares[size_t(k)] + double(ink[size_t(k)]) * ink[size_t(k)];
  }
  // Squared error of the mean over [a, b).
  auto error = [&](int a, int b) {
    if (b <= a) return 0.0;
    const double s = sum[size_t(b)] - sum[size_t(a)];
    return squares[size_t(b)] - squares[size_t(a)] - s * s / double(b - a);
  };
  auto mean = [&](int a, int b) { return b > a ? float((sum[size_t(b)] - sum[size_t(a)]) / double(b - a)) : 0.0f; };
  // Best steps lie where the ink changes (a step inside a run of equal values only moves error
  // from one side to the other), and a texel changes at a few layers only.
  std::vector<int> changes;
  for (int k = 1; k < n; ++k)
    if (ink[size_t(k)] != ink[size_t(k) - 1]) changes.push_back(k);
  TwoSteps best;
  double best_error = 1e300;
  for (size_t i = 0; i < changes.size(); ++i)
    for (size_t j = i; j < changes.size(); ++j) {
      const int k1 = changes[i], k2 = changes[j];
      // Zero before k1 (the layers only gain ink, and the lightest is bare paper).
      const double e = squares[size_t(k1)] + error(k1, k2) + error(k2, n);
      if (e < best_error) best_error = e, best = {k1, k2, mean(k1, k2), mean(k2, n)};
    }
  if (best.k1 == best.k2) best.first = best.second;
  return best;
}

}  // namespace

Image tone_thresholds(const HatchTones& tones) {
  const std::vector<Image>& layers = tones.layers;
  if (layers.size() < 2) throw Error("tone thresholds: need at least two layers");
  const int w = layers.back().width, h = layers.back().height;
  Image out(w, h, {255, 0, 255, 0});
  // A step at layer k sits halfway between the tones of layers k - 1 and k.
  const float step = 1.0f / float(layers.size() - 1);
  auto tone_byte = [&](int k) { return uint8_t(std::clamp((float(k) - 0.5f) * step, 0.0f, 1.0f) * 255.0f + 0.5f); };
  std::vector<uint8_t> known(size_t(w) * size_t(h), 0);
  std::vector<float> ink(layers.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (size_t k = 0; k < layers.size(); ++k) ink[k] = layers[k].at(x, y)[3];
      if (ink.back() == 0) continue;
      const TwoSteps s = fit_two_steps(ink);
      uint8_t* p = out.at(x, y);
      p[0] = tone_byte(s.k1);
      p[1] = uint8_t(std::clamp(s.first, 0.0f, 255.0f) + 0.5f);
      p[2] = tone_byte(s.k2);
      p[3] = uint8_t(std::clamp(s.second, 0.0f, 255.0f) + 0.5f);
      known[size_t(y) * size_t(w) + size_t(x)] = 1;
    }
  // Bare texels grow in from their inked neighbours (wrapping, as the tile does) one ring at a
  // time, each taking the lowest tones around it.
  for (bool grew = true; grew;) {
    grew = false;
    std::vector<uint8_t> next = known;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (known[size_t(y) * size_t(w) + size_t(x)]) continue;
        int first = 256, second = 256;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = (x + dx + w) % w, ny = (y + dy + h) % h;
            if (!known[size_t(ny) * size_t(w) + size_t(nx)]) continue;
            first = std::min(first, int(out.at(nx, ny)[0]));
            second = std::min(second, int(out.at(nx, ny)[2]));
          }
        if (first == 256) continue;
        out.at(x, y)[0] = uint8_t(first);
        out.at(x, y)[2] = uint8_t(second);
        next[size_t(y) * size_t(w) + size_t(x)] = 1;
        grew = true;
      }
    known = std::move(next);
  }
  return out;
}

double ink_coverage(const Image& layer) {
  size_t inked = 0;
  for (size_t i = 3; i < layer.pixels.size(); i += 4) inked += layer.pixels[i] > 127;
  return double(inked) / double(layer.width * layer.height);
}

}  // namespace inkwire
