// The smudge tone (charcoal): the surface itself, to find where it turns away from the eye
// (near the outline) and from the light (its dark side). Both per pixel: across a coarse
// mesh's last ring of triangles the surface turns from half-facing to edge-on.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model_view_projection;
uniform vec3 eye_object;
out vec3 surface_normal;
out vec3 to_eye;
void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  surface_normal = normal;
  to_eye = eye_object - position;
}
