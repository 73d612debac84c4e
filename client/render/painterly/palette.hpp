#pragma once
// Paints (SPEC P7): the colour a brush lays down, from the colour sampled under it.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/image.hpp"

namespace inkwire {

enum class PaletteKind {
  Natural,     // the sampled colour, saturation adjusted
  Shades,      // n shades of one tint by brightness: exactly n colours
  Posterise,   // each channel quantised to n levels
  Sepia,       // brightness mapped onto an old photograph's browns
  FalseColour, // brightness mapped onto a blue-green-yellow-red ramp
  Neon,        // hue snapped to a few glowing colours, dark stays dark
  Lookup,      // brightness indexes a ramp read from an image (its middle row)
};

struct Palette {
  PaletteKind kind = PaletteKind::Natural;
  int shades = 6;                 // Shades, Posterise
  float saturation = 1.0f;        // Natural: 1 keeps, >1 strengthens
  glm::vec3 tint{1.0f};           // Shades: the colour of the brightest shade
  std::vector<glm::vec3> ramp;    // Lookup: colours from dark to light

  // `rgb` and the result in 0..1.
  glm::vec3 apply(glm::vec3 rgb) const;
};

// "natural", "shades", "posterise", "sepia", "false-colour", "neon", "lookup". Throws
// inkwire::Error naming the known kinds.
PaletteKind palette_kind(const std::string& name);
const std::vector<std::string>& palette_kind_names();
// The ramp of a lookup image: its middle row, left (dark) to right (light).
std::vector<glm::vec3> ramp_from_image(const Image& image);

float luminance(glm::vec3 rgb);

}  // namespace inkwire
