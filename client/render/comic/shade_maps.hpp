#pragma once
// Shade maps for the comic renderers (SPEC C1, C3, C4). A shade map is an image indexed by
// N.L along x (left 0, right 1) and R.V up y (bottom 0, top 1; the standard renderer uses the
// bottom row only). Each channel encodes what light does to the object's own colour:
//   0..128   multiplies it (128 = the colour itself, 0 = black),
//   128..255 lifts it toward white (255 = white, for highlights).
// So a mid-grey image leaves objects unshaded, and per-channel values make coloured light.
// Any image file drawn that way can be loaded as a shade map.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "common/image.hpp"

namespace inkwire {

struct ShadeMapOptions {
  int bands = 3;                    // "comic": number of diffuse bands
  std::vector<float> band_edges;    // "comic": N.L where bands change (empty: equal spacing)
  float shadow = 0.24f;             // darkest band is this much darker than the lit band
  float highlight_threshold = 0.96f; // R.V above which the highlight band starts (0: none)
  float highlight = 0.7f;           // how far the highlight lifts toward white
};

struct ShadeMap {
  Image image;
  bool smooth = false;  // sample with linear filtering (near-Phong, chrome); else sharp bands
};

// Names of the generated maps: comic, two-tone, flat, lines, checker, metal, phong, warm-cool.
const std::vector<std::string>& shade_map_names();

// Makes a named map. Throws inkwire::Error for an unknown name or bad options.
ShadeMap make_shade_map(const std::string& name, const ShadeMapOptions& options = {});

// Loads a shade map drawn as an image (see the encoding above). Throws inkwire::Error.
ShadeMap load_shade_map(const std::string& file, bool smooth);

// Encodings of one channel.
inline uint8_t shade_texel(float factor) { return uint8_t(std::clamp(factor, 0.0f, 1.0f) * 128.0f + 0.5f); }
inline uint8_t lift_texel(float toward_white) { return uint8_t(128.0f + std::clamp(toward_white, 0.0f, 1.0f) * 127.0f + 0.5f); }

}  // namespace inkwire
