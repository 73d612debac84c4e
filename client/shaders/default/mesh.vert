// Default renderer (SPEC G5): one directional light, Gouraud (per-vertex) smooth shading as
// in fixed-function GL, the speed reference every other renderer is measured against.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 colour;
layout(location = 3) in vec2 uv;

uniform mat4 model_view_projection;
uniform vec3 light_object;  // light direction rotated into object space once per frame
uniform float ambient;

out vec4 shaded;
out vec2 texcoord;

void main() {
  float diffuse = max(dot(normalize(normal), light_object), 0.0);
  shaded = vec4(colour.rgb * (ambient + (1.0 - ambient) * diffuse), colour.a);
  texcoord = uv;
  gl_Position = model_view_projection * vec4(position, 1.0);
}
