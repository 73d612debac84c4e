#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model_view_projection;
uniform vec3 light_object;
out float n_dot_l;  // interpolated; the tone lookup happens per pixel
void main() {
  n_dot_l = dot(normalize(normal), light_object);
  gl_Position = model_view_projection * vec4(position, 1.0);
}
