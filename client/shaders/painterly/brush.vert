// One brush per instance: a quad turned to the brush's angle, as long as the stroke texture.
layout(location = 0) in vec2 centre;     // window pixels
layout(location = 1) in vec2 half_size;  // half length (along the stroke), half width
layout(location = 2) in float angle;     // radians, counter-clockwise
layout(location = 3) in float layer;     // shape in the texture array
layout(location = 4) in vec4 paint;      // colour and opacity
uniform vec4 viewport;  // x, y, width, height of the target
out vec2 shape_uv;
flat out float shape_layer;
flat out vec4 brush_paint;
void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
  vec2 offset = corner * half_size;
  float c = cos(angle), s = sin(angle);
  vec2 pixel = centre + vec2(c * offset.x - s * offset.y, s * offset.x + c * offset.y);
  gl_Position = vec4((pixel - viewport.xy) / viewport.zw * 2.0 - 1.0, 0.0, 1.0);
  shape_uv = corner * 0.5 + 0.5;
  shape_layer = layer;
  brush_paint = paint;
}
