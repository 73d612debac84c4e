layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model_view_projection;
uniform vec3 light_object;
#if defined(THRESHOLD)
uniform float threshold_scale;  // 2 / softness: N.L's range over which a stroke fades in
out float threshold_offset;     // N.L in the units of the threshold image (see hatch.frag)
#else
out float n_dot_l;              // interpolated; the tone lookup happens per pixel
#endif
void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  float light = dot(normalize(normal), light_object);
#if defined(THRESHOLD)
  threshold_offset = (1.0 + light) * 0.5 * threshold_scale - 0.5;
#else
  n_dot_l = light;
#endif
}
