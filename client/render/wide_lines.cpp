#include "client/render/wide_lines.hpp"

#include <cstddef>

#include <glm/vec2.hpp>

namespace inkwire {

void append_wide_line(std::vector<WideLineVertex>& out, const glm::vec3& a, const glm::vec3& b, float opacity_a, float opacity_b) {
  append_wide_line_corners(out, [&](bool at_a, float corner) {
    return WideLineVertex{at_a ? a : b, at_a ? b : a, corner, at_a ? opacity_a : opacity_b};
  });
}

void wide_line_attributes(gl::VertexArray& vao, const gl::Buffer& buffer, size_t stride_bytes) {
  const auto stride = GLsizei(stride_bytes);
  vao.attribute(0, buffer, 3, stride, offsetof(WideLineVertex, here));
  vao.attribute(1, buffer, 3, stride, offsetof(WideLineVertex, other));
  vao.attribute(2, buffer, 1, stride, offsetof(WideLineVertex, corner));
  vao.attribute(3, buffer, 1, stride, offsetof(WideLineVertex, opacity));
}

void set_wide_line_uniforms(const gl::Program& program, float width) {
  GLint viewport[4] = {};
  gl::glGetIntegerv(GL_VIEWPORT, viewport);
  program.set("viewport_size", glm::vec2(float(viewport[2]), float(viewport[3])));
  program.set("line_width", width);
}

}  // namespace inkwire
