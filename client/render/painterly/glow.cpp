#include "client/render/painterly/glow.hpp"

#include <algorithm>
#include <vector>

#include "client/render/painterly/wash_map.hpp"

namespace inkwire {

Image glow_image(const Image& reference, const Palette& palette, int radius, int margin, int scale) {
  scale = std::max(scale, 1);
  const int w = (reference.width + 2 * margin + scale - 1) / scale, h = (reference.height + 2 * margin + scale - 1) / scale;
  std::vector<float> planes[4];
  for (auto& p : planes) p.assign(size_t(w) * h, 0.0f);
  for (int cy = 0; cy < h; ++cy)
    for (int cx = 0; cx < w; ++cx) {
      glm::vec3 sum(0.0f);
      int object = 0;
      for (int y = cy * scale - margin; y < (cy + 1) * scale - margin; ++y)
        for (int x = cx * scale - margin; x < (cx + 1) * scale - margin; ++x) {
          if (x < 0 || y < 0 || x >= reference.width || y >= reference.height) continue;
          const uint8_t* p = reference.at(x, y);
          if (p[3] < 128) continue;
          sum += glm::vec3(p[0], p[1], p[2]) / 255.0f;
          ++object;
        }
      if (object == 0) continue;
      const float coverage = float(object) / float(scale * scale);
      const glm::vec3 light = palette.apply(sum / float(object)) * coverage;
      const size_t i = size_t(cy) * w + cx;
      for (int c = 0; c < 3; ++c) planes[c][i] = light[c];
      planes[3][i] = coverage;
    }
  for (auto& p : planes) blur_plane(p, w, h, std::max(1, radius / (2 * scale)));
  Image out(w, h);
  for (size_t i = 0; i < planes[0].size(); ++i)
    for (int c = 0; c < 4; ++c) out.pixels[4 * i + size_t(c)] = uint8_t(std::clamp(planes[c][i], 0.0f, 1.0f) * 255.0f + 0.5f);
  return out;
}

}  // namespace inkwire
