// Sketched lines: the CPU's perturbed strokes as wide lines (common/wide_line.glsl), with
// per-vertex opacity (fading, repetition). Pulled a little toward the viewer so strokes that
// wander across their own surface are not cut by it; the hidden-line depth pass still hides the
// far side.
layout(location = 0) in vec3 position;  // this corner's end
layout(location = 1) in vec3 other;     // the segment's other end
layout(location = 2) in float corner;   // 0-5
layout(location = 3) in float opacity;
uniform mat4 model_view_projection;
uniform float depth_bias;
out float stroke_opacity;
#include "common/wide_line.glsl"
void main() {
  gl_Position = wide_line_corner(model_view_projection * vec4(position, 1.0), model_view_projection * vec4(other, 1.0), int(corner));
  gl_Position.z -= depth_bias * gl_Position.w;
  stroke_opacity = opacity;
}
