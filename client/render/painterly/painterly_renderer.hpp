#pragma once
// "painterly" (SPEC P1-P8): the object is drawn off-screen by a reference renderer, limited to
// its screen rectangle, and painted over the backdrop with textured brushes that drift, seek
// the object and take their colour from the reference. Look and behaviour come from a style
// file (shipped: impressionist, pointillist, watercolour, neon, sepia-study); parameters set
// here override the file's values.
#include <memory>
#include <string>

#include "client/render/painterly/brush_painter.hpp"
#include "client/render/painterly/reference_capture.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

class PainterlyRenderer final : public Renderer {
 public:
  PainterlyRenderer();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  // brushes, visible_fraction, respawn_fraction, brush_side_px, capture_pixels.
  std::map<std::string, double> counters() const override;

 private:
  ReferenceCapture capture_;
  BrushPainter painter_;
  std::string style_key_;
  int settle_ = 30;
  bool fresh_ = true;  // no frame painted since the field was (re)made
};

// The style file named by `params` ("style") with the parameters set there applied over it.
PaintStyle paint_style_from_params(const StyleParams& params);
// Every parameter's value as the painting uses it: "0 takes the style's" shows the style's.
std::map<std::string, std::string> painterly_settings_in_effect(const StyleParams& params);
// The backdrop the configured style file asks for (its "ground"), or "" for the style's default.
std::string painterly_ground(const StyleParams& params);

}  // namespace inkwire
