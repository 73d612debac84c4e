#include "client/render/painterly/palette.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "common/error.hpp"
#include "common/luminance.hpp"

namespace inkwire {

namespace {

const std::vector<std::string> kNames = {"natural", "shades", "posterise", "sepia", "false-colour", "neon", "lookup"};

glm::vec3 along_ramp(const std::vector<glm::vec3>& ramp, float t) {
  if (ramp.empty()) return glm::vec3(t);
  const float x = std::clamp(t, 0.0f, 1.0f) * float(ramp.size() - 1);
  const size_t i = std::min(size_t(x), ramp.size() - 1);
  const size_t j = std::min(i + 1, ramp.size() - 1);
  return glm::mix(ramp[i], ramp[j], x - float(i));
}

// Level i of n spread over 0..1 so that the darkest and the brightest both occur.
float quantise(float v, int n) {
  const int level = std::clamp(int(v * float(n)), 0, n - 1);
  return n == 1 ? 1.0f : float(level) / float(n - 1);
}

glm::vec3 neon(glm::vec3 rgb) {
  static const std::array<glm::vec3, 6> glow = {glm::vec3(1.0f, 0.1f, 0.55f), glm::vec3(1.0f, 0.55f, 0.05f), glm::vec3(0.95f, 1.0f, 0.1f),
                                                glm::vec3(0.2f, 1.0f, 0.3f), glm::vec3(0.05f, 0.9f, 1.0f), glm::vec3(0.6f, 0.25f, 1.0f)};
  const float maxc = std::max({rgb.r, rgb.g, rgb.b}), minc = std::min({rgb.r, rgb.g, rgb.b});
  const float value = maxc;
  if (value < 0.18f) return {0.08f, 0.02f, 0.14f};  // the dark ground neon glows against
  float hue = 0.0f;  // 0..6
  if (maxc - minc > 1e-4f) {
    if (maxc == rgb.r) hue = std::fmod((rgb.g - rgb.b) / (maxc - minc) + 6.0f, 6.0f);
    else if (maxc == rgb.g) hue = (rgb.b - rgb.r) / (maxc - minc) + 2.0f;
    else hue = (rgb.r - rgb.g) / (maxc - minc) + 4.0f;
  } else {
    hue = value * 6.0f;  // greys: brightness picks the tube
  }
  return glow[size_t(std::clamp(int(hue + 0.5f) % 6, 0, 5))] * (0.55f + 0.45f * value);
}

}  // namespace

float luminance(glm::vec3 rgb) { return rec709_luminance(rgb.r, rgb.g, rgb.b); }

const std::vector<std::string>& palette_kind_names() { return kNames; }

PaletteKind palette_kind(const std::string& name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return PaletteKind(i);
  std::string known;
  for (const std::string& n : kNames) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown palette '" + name + "' (known: " + known + ")");
}

std::vector<glm::vec3> ramp_from_image(const Image& image) {
  if (image.empty()) throw Error("palette lookup image is empty");
  std::vector<glm::vec3> ramp(size_t(image.width));
  for (int x = 0; x < image.width; ++x) {
    const uint8_t* p = image.at(x, image.height / 2);
    ramp[size_t(x)] = glm::vec3(p[0], p[1], p[2]) / 255.0f;
  }
  return ramp;
}

glm::vec3 Palette::apply(glm::vec3 rgb) const {
  rgb = glm::clamp(rgb, 0.0f, 1.0f);
  const float y = luminance(rgb);
  switch (kind) {
    case PaletteKind::Natural:
      return glm::clamp(glm::mix(glm::vec3(y), rgb, saturation), 0.0f, 1.0f);
    case PaletteKind::Shades:
      return tint * quantise(y, shades);
    case PaletteKind::Posterise:
      return {quantise(rgb.r, shades), quantise(rgb.g, shades), quantise(rgb.b, shades)};
    case PaletteKind::Sepia:
      return along_ramp({{0.17f, 0.10f, 0.06f}, {0.45f, 0.30f, 0.18f}, {0.76f, 0.62f, 0.43f}, {0.98f, 0.93f, 0.80f}}, y);
    case PaletteKind::FalseColour:
      return along_ramp({{0.10f, 0.05f, 0.45f}, {0.0f, 0.55f, 0.75f}, {0.25f, 0.8f, 0.3f}, {0.98f, 0.85f, 0.1f}, {0.9f, 0.15f, 0.1f}}, y);
    case PaletteKind::Neon:
      return neon(rgb);
    case PaletteKind::Lookup:
      return along_ramp(ramp, y);
  }
  return rgb;
}

}  // namespace inkwire
