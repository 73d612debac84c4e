// The visible edges as wide lines (common/wide_line.glsl): each vertex one corner of a segment.
layout(location = 0) in vec3 position;  // this corner's end
layout(location = 1) in vec3 other;     // the segment's other end
layout(location = 2) in float corner;   // 0-5
uniform mat4 model_view_projection;
#include "common/wide_line.glsl"
void main() {
  gl_Position = wide_line_corner(model_view_projection * vec4(position, 1.0), model_view_projection * vec4(other, 1.0), int(corner));
}
