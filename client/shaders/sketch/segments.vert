// Object-segmentation sketcher (S4): every edge is its own object. A pre-generated sketchy
// line of unit length (x along 0..1, y across, in edge lengths) is mapped onto the edge by the
// edge's transform: p = start + x * (end - start) + y * length * side.
//
// The edges are pulled from data textures by vertex number rather than drawn as instances: one
// plain draw per length bin. (llvmpipe runs its whole vertex pipeline once per instance, which
// cost more than the lines themselves at thousands of edges.) Each segment of a line is a wide
// line's six corners (common/wide_line.glsl).
uniform sampler2D unit_points;  // x, y of every unit line's points, bin by bin, line by line
uniform sampler2D edges;        // three texels an edge: start and opacity; end and which line; side
uniform int points_per_line;    // in this length bin
uniform int first_point;        // where this bin's lines start in unit_points
uniform int first_edge;         // where this bin's edges start in edges
uniform mat4 model_view_projection;
uniform float depth_bias;
out float stroke_opacity;
#include "common/data_texture.glsl"
#include "common/wide_line.glsl"

vec4 point_on_edge(vec3 start, vec3 along, vec3 side, int line, int point) {
  vec2 unit = data_texel(unit_points, first_point + line * points_per_line + point).xy;
  return model_view_projection * vec4(start + unit.x * along + unit.y * length(along) * side, 1.0);
}

void main() {
  // Each edge draws points_per_line - 1 segments of six corners; segment s joins points s, s+1.
  int per_edge = 6 * (points_per_line - 1);
  int edge = first_edge + gl_VertexID / per_edge;
  int vertex = gl_VertexID % per_edge;
  int segment = vertex / 6, corner = vertex % 6;
  vec4 start_and_opacity = data_texel(edges, 3 * edge), end_and_line = data_texel(edges, 3 * edge + 1);
  vec3 side = data_texel(edges, 3 * edge + 2).xyz;
  vec3 start = start_and_opacity.xyz, along = end_and_line.xyz - start;
  int line = int(end_and_line.w);
  // Corners 0, 3, 5 sit at the segment's first end (wide_line.glsl's A), the others at its second.
  bool at_a = corner == 0 || corner == 3 || corner == 5;
  vec4 a = point_on_edge(start, along, side, line, segment), b = point_on_edge(start, along, side, line, segment + 1);
  gl_Position = wide_line_corner(at_a ? a : b, at_a ? b : a, corner);
  gl_Position.z -= depth_bias * gl_Position.w;
  stroke_opacity = start_and_opacity.w;
}
