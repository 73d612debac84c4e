// Lines of any width, antialiased by their coverage, drawn as screen-space quads: what GL 3.3
// core and WebGL2 share (wide lines and GL_LINE_SMOOTH are neither's). A segment from end A to
// end B is two triangles, six vertices (A-, B-, B+) (A-, B+, A+); each vertex carries its own end,
// the other end and its corner number 0-5 (client/render/wide_lines.hpp lays them out).
// Included by the vertex shaders that draw lines: #include "common/wide_line.glsl".
uniform vec2 viewport_size;  // pixels
uniform float line_width;    // pixels across
out float line_across;       // signed distance from the line's middle, pixels (wide_line_coverage)

// A pixel of fringe on either side for the coverage ramp, and past either end so consecutive
// segments of a stroke meet without a gap.
const float LINE_FRINGE = 1.0;

// Clip-space position of corner `corner` whose own end is `here` and other end `there` (both
// clip space).
vec4 wide_line_corner(vec4 here, vec4 there, int corner) {
  bool at_a = corner == 0 || corner == 3 || corner == 5;
  float side = (corner == 0 || corner == 1 || corner == 3) ? -1.0 : 1.0;
  vec2 own = here.xy / here.w * 0.5 * viewport_size, other = there.xy / there.w * 0.5 * viewport_size;
  vec2 a_to_b = at_a ? other - own : own - other;
  float len = length(a_to_b);
  vec2 dir = len > 1e-6 ? a_to_b / len : vec2(1.0, 0.0);
  vec2 normal = vec2(-dir.y, dir.x);
  float half_width = 0.5 * line_width + LINE_FRINGE;
  line_across = side * half_width;
  vec2 pixel = own + side * half_width * normal + (at_a ? -dir : dir) * LINE_FRINGE;
  return vec4(pixel / (0.5 * viewport_size) * here.w, here.z, here.w);
}
