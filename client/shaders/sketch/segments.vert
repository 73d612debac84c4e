#version 450 core
// Object-segmentation sketcher (S4): every edge is its own object. A pre-generated sketchy
// line of unit length (x along 0..1, y across, in edge lengths) is mapped onto the edge by the
// edge's transform: p = start + x * (end - start) + y * length * side.
layout(location = 0) in vec3 edge_start;  // per instance
layout(location = 1) in vec3 edge_end;
layout(location = 2) in vec4 side_and_line;  // unit side direction, then which line to draw
layout(location = 3) in float opacity;

layout(std430, binding = 0) readonly buffer UnitLines { vec2 unit_point[]; };
uniform int points_per_line;  // in this length bin
uniform int first_point;      // where this bin's lines start in unit_point
uniform mat4 model_view_projection;
uniform float depth_bias;
out float stroke_opacity;

void main() {
  // GL_LINES: vertex 2s and 2s+1 are the ends of segment s.
  int point = gl_VertexID / 2 + gl_VertexID % 2;
  int line = int(side_and_line.w);
  vec2 unit = unit_point[first_point + line * points_per_line + point];
  vec3 along = edge_end - edge_start;
  vec3 p = edge_start + unit.x * along + unit.y * length(along) * side_and_line.xyz;
  gl_Position = model_view_projection * vec4(p, 1.0);
  gl_Position.z -= depth_bias * gl_Position.w;
  stroke_opacity = opacity;
}
