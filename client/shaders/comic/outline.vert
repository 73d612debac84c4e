// Outline from back faces (C1): every edge of a face turned away from the viewer as a wide line
// (common/wide_line.glsl) behind the filled front faces, whose depth hides the inner parts,
// leaving a thick outline at the silhouette and thinner lines along creases. What drawing the
// back faces with polygon mode GL_LINE did, which WebGL2 lacks: each edge comes once with the
// normals of the faces beside it and is drawn when either is turned away.
layout(location = 0) in vec3 position;  // this corner's end
layout(location = 1) in vec3 other;     // the edge's other end
layout(location = 2) in float corner;   // 0-5
layout(location = 4) in vec3 normal_a;  // the faces beside the edge (an open edge: the same twice)
layout(location = 5) in vec3 normal_b;
layout(location = 6) in vec4 colour_a;  // their flat colours (C8)
layout(location = 7) in vec4 colour_b;
uniform mat4 model_view_projection;
uniform vec3 eye_object;
flat out vec4 triangle_colour;
#include "common/wide_line.glsl"
void main() {
  // The same sum at all six corners, so a whole quad is kept or dropped.
  vec3 to_eye = eye_object - 0.5 * (position + other);
  bool a_back = dot(normal_a, to_eye) <= 0.0, b_back = dot(normal_b, to_eye) <= 0.0;
  triangle_colour = a_back ? colour_a : colour_b;
  if (!a_back && !b_back) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: nothing drawn
    return;
  }
  gl_Position = wide_line_corner(model_view_projection * vec4(position, 1.0), model_view_projection * vec4(other, 1.0), int(corner));
}
