#pragma once
// A painting style (SPEC P7, P8) as data: palette, brush set, orientation and region rules,
// read from a JSON style file so new looks need no recompiling. Three or more are shipped
// (client/render/painterly/styles/*.json, embedded at build time); any file path works too.
#include <optional>
#include <string>
#include <vector>

#include "client/render/painterly/brush_field.hpp"
#include "client/render/painterly/brush_shapes.hpp"
#include "client/render/painterly/palette.hpp"

namespace inkwire {

enum class OrientationKind {
  Random,    // a fixed random angle per place (hash of position), so a brush keeps its slant
  Constant,  // every stroke at one angle
  Circular,  // around the middle of the picture: atan(y/x) + 90 degrees
  Gradient,  // along contours: across the captured image's brightness gradient
};

struct StrokeOrientation {
  OrientationKind kind = OrientationKind::Gradient;
  float angle_degrees = 0;   // Constant: the angle; others: added
  float jitter_degrees = 0;  // per-brush random spread
};

// "When the paint under a brush looks like this, paint it like that." The first matching rule
// wins; ranges are inclusive, over the sampled colour's luminance and saturation (0..1).
struct RegionRule {
  float luminance_min = 0, luminance_max = 1;
  float saturation_min = 0, saturation_max = 1;
  std::vector<BrushShape> shapes;           // empty: the style's
  float size = 1.0f;                        // times the automatic size
  std::optional<StrokeOrientation> orientation;
  std::optional<float> opacity;
  std::optional<Palette> palette;

  bool matches(glm::vec3 rgb) const;
};

struct PaintStyle {
  std::string name;
  int brushes = 3000;
  std::vector<BrushShape> shapes = {BrushShape::Stroke};
  float aspect = 3.0f;       // stroke length over width
  float coverage = 0.98f;    // share of the object the brushes cover between them (SPEC P6)
  float opacity = 0.9f;      // thick (1) to watery paint
  int colour_frames = 4;     // frames each brush averages its colour over
  float underpaint = 0.8f;   // opacity of a blurred base coat inside the matte (0: none)
  float colour_jitter = 0.0f;  // per-brush random shift of the sampled colour: broken colour
  // The medium (SPEC P3, P7): how paint meets the paper and the outline.
  float edge_softness = 0.35f;  // share of a brush's side over which paint fades across the outline (0: a hard cut-out)
  bool glaze = false;           // transparent paint that darkens what is under it (watercolour) instead of covering it
  float wet_edges = 0.0f;       // pigment gathered where a wash ends: the outline and colour boundaries (0..1)
  float granulation = 0.0f;     // pigment settled in the paper's valleys (0..1)
  float glow = 0.0f;            // light the paint gives off around itself (neon; 0: none)
  float glow_radius = 0.05f;    // how far the glow reaches, as a share of the picture's larger side
  std::string ground;           // the backdrop the style is meant for ("#rrggbb", "paper", ...), when the user names none
  Palette palette;
  StrokeOrientation orientation;
  MotionSettings motion;
  std::vector<RegionRule> regions;
};

// Parses a style file's text. Unknown keys, wrong types and out-of-range values are refused
// with a one-line inkwire::Error naming `source` and the key.
PaintStyle parse_paint_style(const std::string& json_text, const std::string& source);
// A shipped style by name ("impressionist"), or a path to a .json file.
PaintStyle load_paint_style(const std::string& name_or_path);
std::vector<std::string> shipped_paint_styles();

}  // namespace inkwire
