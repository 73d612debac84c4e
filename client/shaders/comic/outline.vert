#version 450 core
// Outline from back faces drawn as wide lines behind the filled front faces (C1).
layout(location = 0) in vec3 position;
layout(location = 4) in vec4 flat_colour;
uniform mat4 model_view_projection;
flat out vec4 triangle_colour;
void main() {
  triangle_colour = flat_colour;
  gl_Position = model_view_projection * vec4(position, 1.0);
}
