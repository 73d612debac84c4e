#version 450 core
// Outline from explicit edges (silhouettes, creases), joined into chains and simplified on
// the CPU, drawn as wide lines (cheaper per segment than quads in software GL).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 line_colour;
uniform mat4 model_view_projection;
flat out vec3 edge_colour;
void main() {
  edge_colour = line_colour;
  gl_Position = model_view_projection * vec4(position, 1.0);
}
