#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model_view_projection;
uniform vec3 light_object;
uniform mat2 screen_to_tile;  // rotation and repeat scale
uniform vec2 viewport;
// The strokes lie on the screen: their tile coordinates are an affine map of the window
// position, interpolated linearly across it (cheaper per pixel than reading gl_FragCoord).
noperspective out vec2 tile;
#if defined(THRESHOLD)
uniform float threshold_scale;  // 2 / softness: N.L's range over which a stroke fades in
out float threshold_offset;     // N.L in the units of the threshold image (see hatch.frag)
#else
out float n_dot_l;              // interpolated; the tone lookup happens per pixel
#endif
void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  tile = screen_to_tile * ((gl_Position.xy / gl_Position.w * 0.5 + 0.5) * viewport);
  float light = dot(normalize(normal), light_object);
#if defined(THRESHOLD)
  threshold_offset = (1.0 + light) * 0.5 * threshold_scale - 0.5;
#else
  n_dot_l = light;
#endif
}
