#pragma once
// The default renderer (SPEC G5), the speed reference (100%): back-face culling, depth test,
// one directional light, smooth shading, texture where present, geometry uploaded once.
#include <array>
#include <memory>
#include <optional>

#include "client/render/gpu_mesh.hpp"
#include "client/render/renderer.hpp"

namespace inkwire {

class DefaultRenderer final : public Renderer {
 public:
  DefaultRenderer();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;

 private:
  // Without and with the base texture: a uniform branch around the texture read still costs
  // every fragment the read under llvmpipe, and the speed reference must not pay for that.
  std::array<gl::Program, 2> programs_;
  std::unique_ptr<GpuMesh> mesh_;
  float ambient_ = 0.2f;
};

}  // namespace inkwire
