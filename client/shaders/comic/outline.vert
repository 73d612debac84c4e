#version 450 core
// Outline pass (C1): back faces drawn as wide lines behind the filled front faces.
layout(location = 0) in vec3 position;
uniform mat4 model_view_projection;
void main() { gl_Position = model_view_projection * vec4(position, 1.0); }
