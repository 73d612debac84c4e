#version 450 core
in vec3 coord;
in float stroke_opacity;
in float along;
flat in float run_length;
uniform sampler2DArray strokes;
uniform float strength;
out vec4 colour;
void main() {
  vec4 mark = texture(strokes, coord);
  // Fade in over the first half-width and out over the last: the overrun past each end.
  float ends = clamp(min(along, run_length - along), 0.0, 1.0);
  colour = vec4(mark.rgb, mark.a * stroke_opacity * strength * ends);
}
