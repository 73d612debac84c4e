#pragma once
// Lines of any width as screen-space quads (client/shaders/common/wide_line.glsl): what GL 3.3
// core and WebGL2 share, where glLineWidth above 1 and GL_LINE_SMOOTH are desktop GL's alone.
// A segment is six vertices (two triangles), each carrying its own end, the other end, its
// corner number and the stroke's opacity there; the vertex shader pushes the corners out in
// pixels, the fragment shader fades the edges by coverage.
#include <vector>

#include <glm/vec3.hpp>

#include "client/gl/resources.hpp"

namespace inkwire {

struct WideLineVertex {
  glm::vec3 here, other;
  float corner;
  float opacity;
};

// Whether corner 0-5 of a segment lies at its end A (wide_line.glsl: corners 0, 3, 5) or at B.
constexpr bool wide_line_corner_at_a(int corner) { return corner == 0 || corner == 3 || corner == 5; }

// Appends a segment's six corners as make(at_a, corner): for vertices carrying more than
// WideLineVertex does (a colour, the faces beside an edge), laid out by their own attributes.
template <class Vertex, class Make>
void append_wide_line_corners(std::vector<Vertex>& out, Make make) {
  for (int corner = 0; corner < 6; ++corner) out.push_back(make(wide_line_corner_at_a(corner), float(corner)));
}

// Appends the segment from a to b (opacity at each end).
void append_wide_line(std::vector<WideLineVertex>& out, const glm::vec3& a, const glm::vec3& b, float opacity_a = 1.0f,
                      float opacity_b = 1.0f);
// Points attributes 0-3 of `vao` (here, other, corner, opacity) at `buffer` of WideLineVertex, or
// of a larger vertex of `stride` bytes that begins with one.
void wide_line_attributes(gl::VertexArray& vao, const gl::Buffer& buffer, size_t stride = sizeof(WideLineVertex));
// The uniforms the shaders need: the bound viewport's size and the width in pixels.
void set_wide_line_uniforms(const gl::Program& program, float width);

}  // namespace inkwire
