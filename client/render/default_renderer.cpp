#include "client/render/default_renderer.hpp"

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

DefaultRenderer::DefaultRenderer()
    : programs_{Program::from_files({"default/mesh.vert", "default/mesh.frag"}),
                Program::from_files({"default/mesh.vert", "default/mesh.frag"}, {"TEXTURED 1"})} {}

std::vector<ParamSpec> DefaultRenderer::params() {
  return {float_param("ambient", "0.2", 0, 1, "light reaching faces turned away from the light")};
}

void DefaultRenderer::configure(const StyleParams& params) { ambient_ = params.get_float("ambient"); }

void DefaultRenderer::prepare(const SceneObject& object) { mesh_ = std::make_unique<GpuMesh>(object); }

void DefaultRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("DefaultRenderer::draw(): prepare() was not called");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glDisable(GL_BLEND);
  for (const Program& program : programs_) {
    program.use();
    program.set("model_view_projection", frame.model_view_projection());
    program.set("light_object", frame.light_in_object_space());
    program.set("ambient", ambient_);
    program.set("base_texture", 0);  // absent from the untextured program: ignored there
  }
  mesh_->bind();
  for (const GpuBatch& batch : mesh_->batches()) {
    programs_[batch.textured].use();
    mesh_->draw(batch, 0);
  }
}

}  // namespace inkwire
