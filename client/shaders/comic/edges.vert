// Outline from explicit edges (silhouettes, creases), joined into chains and simplified on
// the CPU, drawn as wide lines (common/wide_line.glsl) in each segment's colour.
layout(location = 0) in vec3 position;  // this corner's end
layout(location = 1) in vec3 other;     // the segment's other end
layout(location = 2) in float corner;   // 0-5
layout(location = 4) in vec3 line_colour;
uniform mat4 model_view_projection;
flat out vec3 edge_colour;
#include "common/wide_line.glsl"
void main() {
  edge_colour = line_colour;
  gl_Position = wide_line_corner(model_view_projection * vec4(position, 1.0), model_view_projection * vec4(other, 1.0), int(corner));
}
