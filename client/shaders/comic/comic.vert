// Comic shading (SPEC C1, C3): per-vertex lighting terms become shade-map coordinates, and it
// is the coordinates, not colours, that are interpolated across each triangle, so band
// boundaries run smoothly through triangles.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 3) in vec2 uv;
layout(location = 4) in vec4 flat_colour;

uniform mat4 model_view_projection;
uniform vec3 light_object;     // light direction in object space, rotated once per frame (C2)
uniform vec3 view_object;      // constant view vector, viewer to bounding-box centre (C5)
uniform vec3 eye_object;       // viewer position, for the exact per-vertex view vector
uniform bool exact_view;
uniform float light_dot_view;  // L.V, once per object when the view vector is constant

out vec2 shade_coord;  // (N.L, R.V)
out vec2 texcoord;
flat out vec4 triangle_colour;  // one colour per triangle, never interpolated (C7)

void main() {
  vec3 n = normalize(normal);
  float n_dot_l = dot(n, light_object);
  shade_coord.x = max(n_dot_l, 0.0);
#ifdef EXTENDED
  vec3 v = exact_view ? normalize(position - eye_object) : view_object;
  float l_dot_v = exact_view ? dot(light_object, v) : light_dot_view;
  // R.V = L.V - 2 (N.L)(N.V): N.V is the orientation test's own term, so this is nearly free.
  // Where the light does not reach (N.L <= 0) there is nothing to reflect.
  shade_coord.y = n_dot_l > 0.0 ? max(l_dot_v - 2.0 * n_dot_l * dot(n, v), 0.0) : 0.0;
#else
  shade_coord.y = 0.0;
#endif
  texcoord = uv;
  triangle_colour = flat_colour;
  gl_Position = model_view_projection * vec4(position, 1.0);
}
