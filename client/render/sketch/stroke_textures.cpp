#include "client/render/sketch/stroke_textures.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec3.hpp>

#include "common/error.hpp"
#include "common/noise.hpp"
#include "common/shaping.hpp"

namespace inkwire {

std::vector<Image> make_stroke_textures(Medium medium, int variants, int length, int width, uint32_t seed) {
  if (variants < 1 || variants > 64 || length < 16 || length > 2048 || width < 4 || width > 256)
    throw Error("stroke textures: sizes out of range");
  std::vector<Image> out;
  for (int k = 0; k < variants; ++k) {
    const uint32_t s = seed * 131u + uint32_t(k) * 7919u;
    // Noise periods divide the strip's length so every texture tiles along u.
    const TileableNoise wander(4, s), edge(16, s + 1), grain(length / 2, s + 2), clumps(length / 8, s + 3);
    Image img(length, width);
    for (int y = 0; y < width; ++y)
      for (int x = 0; x < length; ++x) {
        const float u = float(x) / float(length), v = (float(y) + 0.5f) / float(width);
        // The stroke's centre wanders a little and its edges are ragged.
        const float centre = 0.5f + 0.08f * (wander.at(u * 4, 0.5f) - 0.5f);
        const float across = std::abs(v - centre) * 2.0f;  // 0 at the centre, 1 at the strip's edge
        const float rag = edge.at(u * 16, v * 4) - 0.5f;
        const float g = grain.at(u * float(length) / 2, v * float(width) / 4);
        const float c = clumps.at(u * float(length) / 8, v * 2);
        float alpha = 0.0f;
        glm::vec3 colour(0.0f);
        switch (medium) {
          case Medium::Pencil: {
            // Graphite: a narrow soft core, caught by the paper's tooth.
            const float core = std::exp(-std::pow((across + 0.15f * rag) / 0.55f, 2.0f));
            alpha = core * std::clamp(0.55f + 1.2f * (g - 0.35f), 0.0f, 1.0f);
            colour = glm::vec3(0.16f, 0.16f, 0.19f);
            break;
          }
          case Medium::Charcoal: {
            // Charcoal: broad and dark, crumbling edges, heavy grain with clumps.
            const float band = 1.0f - smoothstep(0.55f, 0.95f, across + 0.35f * rag);
            alpha = band * std::clamp(0.15f + 1.3f * g * (0.6f + 0.6f * c), 0.0f, 1.0f);
            colour = glm::vec3(0.07f, 0.06f, 0.06f);
            break;
          }
          case Medium::Chalk: {
            // Chalk: dry, broken by the surface, lots of gaps.
            const float band = 1.0f - smoothstep(0.45f, 0.9f, across + 0.4f * rag);
            alpha = band * smoothstep(0.38f, 0.62f, g * (0.7f + 0.5f * c));
            colour = glm::vec3(0.95f, 0.95f, 0.9f);
            break;
          }
        }
        uint8_t* p = img.at(x, y);
        for (int i = 0; i < 3; ++i) p[i] = uint8_t(colour[i] * 255.0f + 0.5f);
        p[3] = uint8_t(std::clamp(alpha, 0.0f, 1.0f) * 255.0f + 0.5f);
      }
    out.push_back(std::move(img));
  }
  return out;
}

}  // namespace inkwire
