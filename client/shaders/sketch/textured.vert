// Textured strokes (S5): quads built on the CPU, widened across the edge and the view.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 stroke_coord;  // u along (repeats), v across, texture variant
layout(location = 2) in float opacity;      // edge fading (S6) and how dark the pressure makes it
layout(location = 3) in vec2 run;           // distance along the quad and its length, in half-widths
layout(location = 4) in float pressure;     // 0..1: how hard the stick is pressed here
uniform mat4 model_view_projection;
uniform float depth_bias;
out vec3 coord;
out float stroke_opacity;
out float along;
out float stroke_pressure;
flat out float run_length;
void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  gl_Position.z -= depth_bias * gl_Position.w;
  coord = stroke_coord;
  stroke_opacity = opacity;
  along = run.x;
  run_length = run.y;
  stroke_pressure = pressure;
}
