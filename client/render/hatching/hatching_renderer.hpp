#pragma once
// "hatching" (SPEC S7): hatch strokes in screen space (rotated and scaled), made visible by a
// shade lookup indexed by N.L and used as alpha per pixel (per-vertex alpha pops on coarse
// meshes). Tones come from layers where lighter stroke sets are subsets of darker ones.
// Variants:
//   threshold   (default) one pass reading one 2D texture that holds, per texel, the N.L
//               below which its stroke appears (the nested layers folded into one image, and
//               the shade lookup folded into its thresholds)
//   3d-texture  one pass sampling a 3D texture whose depth axis is tone
//   multipass   one pass per tone layer, each fading in as the tone passes it
// Every variant draws a light tone over the lit surface, crosses its strokes below a chosen N.L
// and draws an outline (a pencil sketcher's by default) over the hatching.
// When the frame says what its backdrop is, the one-pass variants draw the surface opaque with
// the backdrop under the ink, depth-tested like any surface; otherwise (and for multipass) the
// object's depth is laid first (G7) and the ink blended over the framebuffer, so only the
// visible surface is hatched and the paper shows through between strokes either way.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

// The shade lookup: the tone (0 paper .. 1 darkest) of a surface at a given N.L.
struct ShadeLookup {
  float lightness = 0.85f;   // N.L above which the surface has only the light tone
  float light_tone = 0.15f;  // the least tone anywhere on the surface
  float tone_at(float n_dot_l) const;     // never lighter as N.L falls
  float n_dot_l_at(float tone) const;     // the N.L below which the surface reaches `tone`
};

class HatchingRenderer final : public Renderer {
 public:
  static std::vector<ParamSpec> params();
  // The styles `outline` may name: lines that, like hatching, keep still on a still object.
  static std::vector<std::string> outline_styles();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  bool left_line_depth() const override { return opaque_; }
  std::map<std::string, double> counters() const override;

 private:
  void build_textures();
  int threshold_size() const;  // texels of the threshold image: the tile's size on screen
  bool pixel_exact() const;    // a threshold texel is a pixel
  const gl::Program& program(const std::string& under_define);

  std::map<std::string, gl::Program> programs_;  // by variant and backdrop define
  HiddenLineRemoval hlr_;
  std::unique_ptr<GpuMesh> mesh_;
  std::unique_ptr<gl::Texture> tones_, tone_lookup_;

  const SceneObject* object_ = nullptr;
  std::unique_ptr<Renderer> outline_;  // drawn over the hatching; none when "none"
  std::string outline_name_ = "none";

  std::string variant_ = "threshold";
  int tone_layers_ = 16, passes_wanted_ = 4;
  ShadeLookup shade_;
  float cross_below_ = 0.3f;
  float angle_ = 0.0f, scale_px_ = 96.0f, strength_ = 0.9f;
  size_t passes_ = 0;
  bool opaque_ = false;
};

}  // namespace inkwire
