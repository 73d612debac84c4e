#include "client/render/hidden_line_renderer.hpp"

#include <glm/trigonometric.hpp>

#include "common/orientation.hpp"

#include "common/error.hpp"

namespace inkwire {

using namespace gl;

HiddenLineRenderer::HiddenLineRenderer() : lines_(Program::from_files({"hidden-line/lines.vert", "hidden-line/lines.frag"})) {
  line_vao_ = VertexArray::create();
  line_buffer_ = Buffer::create(0, nullptr, GL_STREAM_DRAW);
  wide_line_attributes(line_vao_, line_buffer_);
}

std::vector<ParamSpec> HiddenLineRenderer::params() {
  return {
      float_param("line_width", "2", 1, 10, "line width in pixels"),
      float_param("crease_degrees", "60", 0, 180, "draw edges whose faces meet at a sharper angle than this"),
      colour_param("colour", "#1a1a1a", "line colour"),
  };
}

void HiddenLineRenderer::configure(const StyleParams& params) {
  line_width_ = params.get_float("line_width");
  crease_radians_ = glm::radians(params.get_float("crease_degrees"));
  line_colour_ = params.get_colour("colour");
}

void HiddenLineRenderer::prepare(const SceneObject& object) {
  object_ = &object;
  mesh_ = std::make_unique<GpuMesh>(object);
}

void HiddenLineRenderer::draw(const FrameState& frame) {
  if (!mesh_) throw Error("HiddenLineRenderer::draw(): prepare() was not called");
  const Mesh& mesh = object_->mesh;
  const glm::vec3 eye_object = frame.eye_in_object_space();
  front_faces_ = classify_faces(mesh, object_->topology, eye_object, front_);
  line_vertices_.clear();
  for (const Edge& e : object_->topology.edges)
    if (e.boundary || e.dihedral > crease_radians_ || is_silhouette(e, front_)) append_wide_line(line_vertices_, mesh.positions[e.v0], mesh.positions[e.v1]);
  const glm::mat4 mvp = frame.model_view_projection();
  hlr_.lay_depth(*mesh_, frame);

  HiddenLineRemoval::begin_lines();
  line_buffer_.upload(line_vertices_.size() * sizeof(WideLineVertex), line_vertices_.data());
  lines_.use();
  lines_.set("model_view_projection", mvp);
  lines_.set("line_colour", glm::vec4(line_colour_, 1.0f));
  set_wide_line_uniforms(lines_, line_width_);
  line_vao_.bind();
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(line_vertices_.size()));
  HiddenLineRemoval::end_lines();
}

std::map<std::string, double> HiddenLineRenderer::counters() const {
  return {{"edges_total", double(object_ ? object_->topology.edges.size() : 0)},
          {"edges_drawn", double(line_vertices_.size() / 6)},
          {"front_faces", double(front_faces_)}};
}

}  // namespace inkwire
