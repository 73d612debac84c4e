#include "client/render/painterly/painterly_renderer.hpp"

#include <algorithm>
#include <cstdio>

#include "client/render/backdrop.hpp"
#include "client/render/styles.hpp"

namespace inkwire {

PainterlyRenderer::PainterlyRenderer() = default;

namespace {

// A painting's reference is any style that draws the object itself (not another painting).
std::vector<std::string> reference_styles() {
  std::vector<std::string> names = style_names();
  std::erase_if(names, [](const std::string& n) { return n == "painterly" || n == "oil-filter" || n == "tween"; });
  return names;
}

const char* orientation_name(OrientationKind kind) {
  switch (kind) {
    case OrientationKind::Random: return "random";
    case OrientationKind::Constant: return "constant";
    case OrientationKind::Circular: return "circular";
    case OrientationKind::Gradient: break;
  }
  return "gradient";
}

}  // namespace

std::vector<ParamSpec> PainterlyRenderer::params() {
  std::vector<std::string> palettes = {"style"};
  for (const std::string& p : palette_kind_names())
    if (p != "lookup") palettes.push_back(p);  // a lookup needs its image: style files only
  return {
      file_param("style", "impressionist", "a shipped painting style or a style file (.json)", shipped_paint_styles()),
      text_param("reference", "default", "the style whose picture is painted", reference_styles()),
      int_param("brushes", "0", 0, 100000, "number of brushes; 0 takes the style's"),
      float_param("coverage", "0", 0, 0.999, "share of the object the brushes cover between them; 0 takes the style's"),
      choice_param("palette", "style", palettes, "paint colours; 'style' takes the style's"),
      int_param("shades", "0", 0, 64, "shades/posterise levels; 0 takes the style's"),
      choice_param("orientation", "style", {"style", "random", "constant", "circular", "gradient"}, "stroke directions; 'style' takes the style's"),
      float_param("angle", "0", -360, 360, "constant orientation: the angle, degrees"),
      int_param("ttl", "0", 0, 1000, "frames a lost brush searches before respawning; 0 takes the style's"),
      bool_param("randomise_ttl", "true", "spread respawns over frames (false: every lost brush gets the same time-to-live)"),
      float_param("underpaint", "-1", -1, 1, "opacity of the blurred base coat; -1 takes the style's"),
      float_param("edge_softness", "-1", -1, 2, "share of a brush over which paint fades across the outline (0: a hard cut-out); -1 takes the style's"),
      float_param("glow", "-1", -1, 4, "strength of the light the paint gives off around itself; -1 takes the style's"),
      int_param("settle", "30", 0, 1000, "simulation steps before the first frame, so a still image shows settled brushes"),
      int_param("seed", "1", 0, 1 << 30, "random seed of the brush field"),
  };
}

PaintStyle paint_style_from_params(const StyleParams& p) {
  PaintStyle style = load_paint_style(p.get_text("style"));
  if (const int n = p.get_int("brushes"); n > 0) style.brushes = n;
  if (const float c = p.get_float("coverage"); c > 0) style.coverage = std::max(c, 0.3f);
  if (p.get_text("palette") != "style") style.palette.kind = palette_kind(p.get_text("palette"));
  if (const int n = p.get_int("shades"); n > 0) style.palette.shades = n;
  if (const std::string& o = p.get_text("orientation"); o != "style") {
    style.orientation.kind = o == "random" ? OrientationKind::Random : o == "constant" ? OrientationKind::Constant
                           : o == "circular" ? OrientationKind::Circular : OrientationKind::Gradient;
    style.orientation.angle_degrees = p.get_float("angle");
  }
  if (const int ttl = p.get_int("ttl"); ttl > 0) style.motion.time_to_live = ttl;
  style.motion.randomise_ttl = p.get_bool("randomise_ttl");
  if (const float u = p.get_float("underpaint"); u >= 0) style.underpaint = u;
  if (const float e = p.get_float("edge_softness"); e >= 0) style.edge_softness = e;
  if (const float g = p.get_float("glow"); g >= 0) style.glow = g;
  return style;
}

std::string painterly_ground(const StyleParams& p) { return paint_style_from_params(p).ground; }

std::map<std::string, std::string> painterly_settings_in_effect(const StyleParams& p) {
  const PaintStyle style = paint_style_from_params(p);
  std::map<std::string, std::string> values = p.values();
  values["brushes"] = std::to_string(style.brushes);
  values["coverage"] = param_number(style.coverage);
  values["palette"] = palette_kind_names()[size_t(style.palette.kind)];
  values["shades"] = std::to_string(style.palette.shades);
  values["orientation"] = orientation_name(style.orientation.kind);
  values["angle"] = param_number(style.orientation.angle_degrees);
  values["ttl"] = std::to_string(style.motion.time_to_live);
  values["underpaint"] = param_number(style.underpaint);
  values["edge_softness"] = param_number(style.edge_softness);
  values["glow"] = param_number(style.glow);
  return values;
}

void PainterlyRenderer::configure(const StyleParams& p) {
  const PaintStyle style = paint_style_from_params(p);
  settle_ = p.get_int("settle");

  // Rebuild only what changed: a new field scatters the brushes, which a user would see.
  std::string key;
  for (const auto& [k, v] : p.values()) key += k + "=" + v + ";";
  if (key != style_key_) {
    painter_.set_style(style, uint64_t(p.get_int("seed")));
    style_key_ = key;
    fresh_ = true;
  }
  capture_.use_renderer(p.get_text("reference"));
}

void PainterlyRenderer::prepare(const SceneObject& object) {
  capture_.prepare(object);
  fresh_ = true;
}

void PainterlyRenderer::draw(const FrameState& frame) {
  const Image& reference = capture_.capture(frame);
  const bool opaque_ground = frame.backdrop && frame.backdrop->spec().kind != BackdropSpec::Kind::None;
  painter_.paint(reference, capture_.rect(), /*underpaint=*/true, fresh_ ? settle_ : 0, opaque_ground);
  fresh_ = false;
}

std::map<std::string, double> PainterlyRenderer::counters() const {
  const BrushField* field = painter_.field();
  if (!field) return {};
  return {{"brushes", double(field->brushes().size())},
          {"visible_fraction", field->visible_fraction()},
          {"respawn_fraction", field->respawn_fraction()},
          {"brush_side_px", painter_.brush_side()},
          {"capture_pixels", capture_.pixels()}};
}

}  // namespace inkwire
