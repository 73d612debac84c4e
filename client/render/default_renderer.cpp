#include "client/render/default_renderer.hpp"

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

DefaultRenderer::DefaultRenderer() : program_(Program::from_files({"default/mesh.vert", "default/mesh.frag"})) {}

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
  program_.use();
  program_.set("model_view_projection", frame.model_view_projection());
  program_.set("light_object", frame.light_in_object_space());
  program_.set("ambient", ambient_);
  program_.set("base_texture", 0);
  mesh_->bind();
  for (const GpuBatch& batch : mesh_->batches()) {
    program_.set("textured", int(batch.textured));
    mesh_->draw(batch, 0);
  }
}

}  // namespace inkwire
