#include "client/render/face/comic_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "common/luminance.hpp"
#include "common/percentile.hpp"
#include "common/polygon.hpp"

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


// Ink as coverage (0..1) over a picture, strokes laid with antialiased edges.
struct Ink {
  int width = 0, height = 0;
  std::vector<float> cover;
  Ink(int w, int h) : width(w), height(h), cover(size_t(w) * size_t(h), 0.0f) {}
  float& at(int x, int y) { return cover[size_t(y) * size_t(width) + size_t(x)]; }

  // A pen stroke through `points`: `ends` wide at both ends, swelling to `middle` halfway along.
  void stroke(std::span<const glm::vec2> points, float ends, float middle) {
    float length = 0;
    for (size_t i = 1; i < points.size(); ++i) length += glm::length(points[i] - points[i - 1]);
    if (length <= 0) return;
    float along = 0;
    for (size_t i = 1; i < points.size(); ++i) {
      const glm::vec2 a = points[i - 1], b = points[i], ab = b - a;
      const float segment = glm::length(ab);
      const float t0 = along / length, t1 = (along + segment) / length;
      along += segment;
      const float reach = middle / 2 + 1;
      const int x0 = std::max(0, int(std::min(a.x, b.x) - reach)), x1 = std::min(width - 1, int(std::max(a.x, b.x) + reach));
      const int y0 = std::max(0, int(std::min(a.y, b.y) - reach)), y1 = std::min(height - 1, int(std::max(a.y, b.y) + reach));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
          const float s = segment > 0 ? std::clamp(glm::dot(p - a, ab) / (segment * segment), 0.0f, 1.0f) : 0.0f;
          const float t = t0 + (t1 - t0) * s;
          const float w = ends + (middle - ends) * 4 * t * (1 - t);
          const float c = std::clamp(w / 2 + 0.5f - glm::length(p - (a + ab * s)), 0.0f, 1.0f);
          at(x, y) = std::max(at(x, y), c);
        }
    }
  }
};

// These landmarks, in this order.
std::vector<glm::vec2> run(const FaceLandmarks& face, std::initializer_list<int> indices) {
  std::vector<glm::vec2> out;
  for (const int i : indices) out.push_back(face[size_t(i)]);
  return out;
}

// The most common of three band indices in each 5x5 neighbourhood: small islands of a tone go,
// borders between tones run smooth, as a cartoonist's fills do.
std::vector<uint8_t> majority(const std::vector<uint8_t>& band, int width, int height) {
  std::vector<uint8_t> out(band.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::array<int, 3> votes{};
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) ++votes[band[size_t(std::clamp(y + dy, 0, height - 1)) * size_t(width) + size_t(std::clamp(x + dx, 0, width - 1))]];
      out[size_t(y) * size_t(width) + size_t(x)] = uint8_t(std::max_element(votes.begin(), votes.end()) - votes.begin());
    }
  return out;
}

}  // namespace

void comic_face(Image& photo, const FaceLandmarks& landmarks, const PersonMatte& matte, glm::u8vec3 ground) {
  if (photo.width < 8 || photo.height < 8 || matte.width != photo.width || matte.height != photo.height) return;
  const int width = photo.width, height = photo.height;
  const size_t count = size_t(width) * size_t(height);
  const float eyes = face_frame(landmarks).scale;
  const auto person = [&](int x, int y) { return matte.at(x, y) >= 128; };

  std::vector<float> grey(count);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = photo.at(x, y);
      grey[size_t(y) * size_t(width) + size_t(x)] = luma(p[0], p[1], p[2]);
    }
  const std::vector<uint8_t> edges = canny_edges(grey, width, height, 60, 150);
  // On the face only the strongest (a glasses' frame), not the soft shadows of its relief.
  const std::vector<uint8_t> face_edges = canny_edges(grey, width, height, 100, 200);

  // Tones: three bands between the person's own darkest and lightest (5th and 95th percentiles of
  // the smoothed light), each filled with its pixels' mean light, the shadow no darker than 48.
  const Plane smooth = bilateral(bilateral(bilateral(half_size(photo))));
  const float sx = float(smooth.width) / float(width), sy = float(smooth.height) / float(height);
  std::vector<Rgb> colour(count);
  std::vector<float> light(count), person_light;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      colour[i] = bilinear(smooth, (float(x) + 0.5f) * sx - 0.5f, (float(y) + 0.5f) * sy - 0.5f);
      light[i] = luma(colour[i].r, colour[i].g, colour[i].b);
      if (person(x, y)) person_light.push_back(light[i]);
    }
  if (person_light.empty()) person_light = light;
  const float low = *percentile_in_place(std::span<float>(person_light), 0.05);
  const float high = std::max(low + 1, *percentile_in_place(std::span<float>(person_light), 0.95));
  const float shadow_below = low + (high - low) * 0.33f, light_above = low + (high - low) * 0.72f;
  std::vector<uint8_t> band(count);
  for (size_t i = 0; i < count; ++i) band[i] = light[i] < shadow_below ? 0 : light[i] < light_above ? 1 : 2;
  band = majority(majority(band, width, height), width, height);
  std::array<float, 3> tone_sum{}, tone_count{};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (person(x, y)) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        tone_sum[band[i]] += light[i], tone_count[band[i]] += 1;
      }
  std::array<float, 3> tone{};
  for (size_t b = 0; b < 3; ++b) tone[b] = tone_count[b] > 0 ? tone_sum[b] / tone_count[b] : low + (high - low) * (0.2f + 0.35f * float(b));
  tone[0] = std::max(tone[0], 48.0f);
  tone[1] = std::max(tone[1], tone[0] + 1), tone[2] = std::max(tone[2], tone[1] + 1);

  // Ink: the features along their landmarks, pen widths in proportion to the face.
  Ink ink(width, height);
  const float fine = std::max(1.0f, eyes * 0.025f), bold = std::max(1.6f, eyes * 0.07f);
  using namespace face_index;
  ink.stroke(run(landmarks, {17, 18, 19, 20, 21}), fine, bold);  // brows
  ink.stroke(run(landmarks, {22, 23, 24, 25, 26}), fine, bold);
  ink.stroke(run(landmarks, {36, 37, 38, 39}), fine, bold * 0.8f);  // upper lids, bold
  ink.stroke(run(landmarks, {42, 43, 44, 45}), fine, bold * 0.8f);
  ink.stroke(run(landmarks, {39, 40, 41, 36}), fine * 0.8f, fine * 1.3f);  // lower lids, fine
  ink.stroke(run(landmarks, {45, 46, 47, 42}), fine * 0.8f, fine * 1.3f);
  ink.stroke(run(landmarks, {31, 32, 33, 34, 35}), fine, bold * 0.6f);  // the nose's base
  ink.stroke(run(landmarks, {60, 61, 62, 63, 64}), fine, bold * 0.7f);  // between the lips
  ink.stroke(run(landmarks, {48, 49, 50, 51, 52, 53, 54}), fine * 0.8f, fine * 1.4f);  // the upper lip
  ink.stroke(run(landmarks, {56, 57, 58}), fine * 0.6f, fine * 1.4f);  // under the lower lip
  ink.stroke(run(landmarks, {4, 5, 6, 7, 8, 9, 10, 11, 12}), fine, fine * 1.8f);  // the jaw over the neck
  // The irises: a dark disc at each eye's middle, a third of the eye's width across, inside its lids.
  for (const int first : {kEyeLeftFirst, kEyeRightFirst}) {
    const std::vector<glm::vec2> eye = run(landmarks, {first, first + 1, first + 2, first + 3, first + 4, first + 5});
    glm::vec2 middle(0);
    for (const glm::vec2& p : eye) middle += p / 6.0f;
    const float radius = glm::distance(eye[0], eye[3]) * 0.19f;
    for (int y = std::max(0, int(middle.y - radius - 1)); y <= std::min(height - 1, int(middle.y + radius + 1)); ++y)
      for (int x = std::max(0, int(middle.x - radius - 1)); x <= std::min(width - 1, int(middle.x + radius + 1)); ++x) {
        const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
        if (!inside_polygon(eye, p)) continue;
        ink.at(x, y) = std::max(ink.at(x, y), 0.9f * std::clamp(radius + 0.5f - glm::distance(p, middle), 0.0f, 1.0f));
      }
  }
  // The person's outline: person pixels within a pen's width of the ground.
  const int outline = std::max(1, int(std::lround(eyes * 0.03f)));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!person(x, y)) continue;
      bool near_ground = false;
      for (int dy = -outline; dy <= outline && !near_ground; ++dy)
        for (int dx = -outline; dx <= outline && !near_ground; ++dx) {
          const int nx = std::clamp(x + dx, 0, width - 1), ny = std::clamp(y + dy, 0, height - 1);
          near_ground = !person(nx, ny);
        }
      if (near_ground) ink.at(x, y) = 1;
    }
  // The photo's strong edges where the landmarks draw nothing: inside the person, and on the face
  // only the strongest.
  std::vector<glm::vec2> face = run(landmarks, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16});
  for (int i = kBrowRightLast; i >= kBrowLeftFirst; --i) face.push_back(landmarks[size_t(i)] - glm::vec2(0, eyes * 0.2f));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (matte.at(x, y) >= 200) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        const bool on_face = inside_polygon(face, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
        if (on_face ? face_edges[i] : edges[i]) ink.at(x, y) = std::max(ink.at(x, y), 0.85f);
      }

  constexpr float kInk[3] = {25, 20, 20};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      const Rgb c = colour[i];
      const float l = light[i], t = tone[band[i]];
      // The pixel's own colour brought to its band's tone (its hue and saturation kept).
      const float gain = l > 8 ? std::min(t / l, 3.0f) : 0;
      const float filled[3] = {l > 8 ? c.r * gain : t, l > 8 ? c.g * gain : t, l > 8 ? c.b * gain : t};
      const float a = float(matte.at(x, y)) / 255.0f, k = ink.at(x, y);
      uint8_t* out = photo.at(x, y);
      for (int ch = 0; ch < 3; ++ch) {
        const float on_ground = float(ground[ch]) + (std::clamp(filled[ch], 0.0f, 255.0f) - float(ground[ch])) * a;
        out[ch] = uint8_t(std::lround(on_ground + (kInk[ch] - on_ground) * k));
      }
    }
}

}  // namespace inkwire
