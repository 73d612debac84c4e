#pragma once
// "hidden-line": a clean line drawing over the backdrop. Per frame, silhouette edges (exact
// per-triangle view vectors, SPEC G3), crease edges sharper than a threshold and open edges
// are drawn as lines, with hidden parts removed by the depth-only pass of SPEC G7.
#include <memory>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"
#include "client/render/wide_lines.hpp"

namespace inkwire {

class HiddenLineRenderer final : public Renderer {
 public:
  HiddenLineRenderer();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  HiddenLineRemoval hlr_;
  gl::Program lines_;
  gl::VertexArray line_vao_;
  gl::Buffer line_buffer_;
  std::vector<uint8_t> front_;
  std::vector<WideLineVertex> line_vertices_;  // six a visible edge
  float line_width_ = 2.0f, crease_radians_ = 1.05f;
  glm::vec3 line_colour_{0.1f};
  size_t front_faces_ = 0;
};

}  // namespace inkwire
