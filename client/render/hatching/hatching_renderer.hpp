#pragma once
// "hatching" (SPEC S7): hatch strokes in screen space (rotated and scaled), made visible by a
// shade lookup indexed by N.L and used as alpha per pixel (per-vertex alpha pops on coarse
// meshes). Tones come from layers where lighter stroke sets are subsets of darker ones.
// Variant "3d-texture" (default): one pass sampling a 3D texture whose depth axis is tone, so
// tones blend smoothly. Variant "multipass": one pass per tone layer, each fading in as the
// tone passes it. Drawn over the backdrop with the object's depth laid first (G7), so only the
// visible surface is hatched and the paper shows through between strokes.
#include <memory>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

class HatchingRenderer final : public Renderer {
 public:
  HatchingRenderer();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  void build_textures();

  gl::Program volume_program_, layer_program_;
  HiddenLineRemoval hlr_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  std::unique_ptr<gl::Texture> volume_, layers_, tone_lookup_;

  bool multipass_ = false;
  int tone_layers_ = 16, passes_wanted_ = 4;
  float angle_ = 0.0f, scale_px_ = 96.0f, lightness_ = 0.85f, strength_ = 0.9f;
  size_t passes_ = 0;
};

}  // namespace inkwire
