#version 450 core
// Sketched lines: positions from the CPU's perturbed strokes, with per-vertex opacity (fading,
// repetition). Pulled a little toward the viewer so strokes that wander across their own
// surface are not cut by it; the hidden-line depth pass still hides the far side.
layout(location = 0) in vec3 position;
layout(location = 1) in float opacity;
uniform mat4 model_view_projection;
uniform float depth_bias;
out float stroke_opacity;
void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  gl_Position.z -= depth_bias * gl_Position.w;
  stroke_opacity = opacity;
}
