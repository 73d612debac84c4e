#include "client/render/hidden_lines.hpp"

namespace inkwire {

using namespace gl;

void begin_smooth_lines() {
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void end_smooth_lines() {
  glDisable(GL_BLEND);
}

HiddenLineRemoval::HiddenLineRemoval()
    : depth_only_(Program::from_files({"common/depth_only.vert", "common/depth_only.frag"})) {}

void HiddenLineRemoval::lay_depth(const GpuMesh& mesh, const FrameState& frame) const {
  if (frame.depth_laid) return;
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  begin_surface_depth();
  depth_only_.use();
  depth_only_.set("model_view_projection", frame.model_view_projection());
  mesh.bind();
  mesh.draw_all();
  end_surface_depth();
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void HiddenLineRemoval::begin_surface_depth() {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 2.0f);
  // LEQUAL: the offset's slope term can clamp edge-on slivers to depth 1.0, which LESS would
  // drop against the clear, letting hidden lines show through there.
  glDepthFunc(GL_LEQUAL);
}

void HiddenLineRemoval::end_surface_depth() {
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthFunc(GL_LESS);
}

void HiddenLineRemoval::begin_lines() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  begin_smooth_lines();
}

void HiddenLineRemoval::end_lines() {
  end_smooth_lines();
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

}  // namespace inkwire
