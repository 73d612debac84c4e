#pragma once
// Lays brushes on the bound framebuffer (SPEC P3-P8): a BrushField simulated on the CPU against
// the reference image, each brush given a look (shape, size, paint, angle) by the style and its
// region rules, then drawn as instanced, textured quads clipped to the object's matte. An
// optional underpainting (a blurred base coat in the palette's colours) goes down first so no
// canvas shows through the object between strokes. The style's medium decides how paint meets
// the outline (a soft fade across it, or the stencil's cut-out), whether it glazes (transparent
// washes) with wet edges and granulation, and whether it glows.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "client/gl/resources.hpp"
#include "client/render/painterly/brush_field.hpp"
#include "client/render/painterly/paint_style.hpp"
#include "client/render/painterly/rect_image.hpp"
#include "client/render/painterly/reference_capture.hpp"
#include "client/render/painterly/wash_map.hpp"

namespace inkwire {

class BrushPainter {
 public:
  BrushPainter();

  // A new style or brush count starts a new field (brushes scattered afresh).
  void set_style(const PaintStyle& style, uint64_t seed);
  const PaintStyle& style() const { return style_; }

  // One frame: steps the brushes against `reference` (top row first; alpha is the matte),
  // which sits at `rect` in the bound framebuffer, and paints them there. `settle` extra
  // steps first let a fresh field find the object before anything is drawn (still images).
  // A glazing style glazes only over an `opaque_ground` (there is nothing to darken over a
  // transparent one); otherwise its paint is laid over as other paint is.
  void paint(const Image& reference, PixelRect rect, bool underpaint, int settle = 0, bool opaque_ground = false);

  const BrushField* field() const { return field_.get(); }
  float brush_side() const { return side_; }

 private:
  struct Look {  // chosen when a brush lands, kept while it stays: no popping between shapes
    int rule = -1;
    BrushShape shape = BrushShape::Stroke;
    bool flipped = false;
    glm::vec3 jitter{0};  // this brush's share of the style's colour jitter
  };
  struct Instance {
    glm::vec2 centre;     // window pixels
    glm::vec2 half_size;  // half width and half length, pixels; negative length mirrors
    float angle;          // radians, counter-clockwise on screen
    float layer;          // shape texture layer
    glm::u8vec4 colour;   // paint and opacity
  };
  void choose_look(size_t index, const Brush& brush);
  float target_angle(size_t index, const Brush& brush, const Image& reference, const StrokeOrientation& orientation) const;
  void draw_underpaint(const Image& reference, PixelRect rect);
  void draw_glow(const Image& reference, PixelRect rect);
  const gl::Program& brush_program(bool soft, bool glaze);
  // Writes the matte into the stencil (1 on the object, or with soft edges as far as paint may
  // fade beyond it) as the base coat is laid, or alone without one, and leaves the stencil test
  // passing only there: brushes then stay on the object without each fragment reading the
  // matte, and fragments beyond a soft edge's reach are never shaded.
  void lay_matte(const Image& reference, PixelRect rect, bool underpaint);

  PaintStyle style_;
  uint64_t seed_ = 1;
  std::unique_ptr<BrushField> field_;
  std::vector<Look> looks_;
  std::vector<Instance> instances_;
  float side_ = 1.0f;

  std::map<int, gl::Program> brush_programs_;  // by the effects compiled in
  gl::Texture shapes_, matte_, coarse_, medium_, glow_;
  WashMapper wash_mapper_;
  std::optional<gl::Texture> tooth_;  // the paper's grain, made when a style granulates
  gl::Buffer instance_buffer_;
  gl::VertexArray brush_vao_;
  RectImage rect_image_;
};

}  // namespace inkwire
