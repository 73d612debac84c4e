#version 450 core
// Object-segmentation sketcher (S4): every edge is its own object. A pre-generated sketchy
// line of unit length (x along 0..1, y across, in edge lengths) is mapped onto the edge by the
// edge's transform: p = start + x * (end - start) + y * length * side.
//
// The edges are pulled from a buffer by vertex number rather than drawn as instances: one
// plain draw per length bin. (llvmpipe runs its whole vertex pipeline once per instance, which
// cost more than the lines themselves at thousands of edges.)
struct Edge {
  vec4 start_and_opacity;
  vec4 end_and_line;  // w: which of the bin's unit lines to draw
  vec4 side;          // unit side direction
};
layout(std430, binding = 0) readonly buffer UnitLines { vec2 unit_point[]; };
layout(std430, binding = 1) readonly buffer Edges { Edge edges[]; };
uniform int points_per_line;  // in this length bin
uniform int first_point;      // where this bin's lines start in unit_point
uniform int first_edge;       // where this bin's edges start in edges
uniform mat4 model_view_projection;
uniform float depth_bias;
out float stroke_opacity;

void main() {
  // GL_LINES: each edge draws points_per_line - 1 segments; vertex 2s and 2s+1 of an edge are
  // the ends of its segment s.
  int per_edge = 2 * (points_per_line - 1);
  Edge e = edges[first_edge + gl_VertexID / per_edge];
  int vertex = gl_VertexID % per_edge;
  int point = vertex / 2 + vertex % 2;
  vec2 unit = unit_point[first_point + int(e.end_and_line.w) * points_per_line + point];
  vec3 start = e.start_and_opacity.xyz;
  vec3 along = e.end_and_line.xyz - start;
  vec3 p = start + unit.x * along + unit.y * length(along) * e.side.xyz;
  gl_Position = model_view_projection * vec4(p, 1.0);
  gl_Position.z -= depth_bias * gl_Position.w;
  stroke_opacity = e.start_and_opacity.w;
}
