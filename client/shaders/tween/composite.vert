// The synthesised view laid over a rectangle of the target (no vertex buffer: corners from
// gl_VertexID).
uniform vec4 viewport;  // x, y, width, height of the target
uniform vec4 rect;      // x, y, width, height in window pixels (GL: y up)
out vec2 uv;
void main() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  vec2 pixel = rect.xy + corner * rect.zw;
  gl_Position = vec4((pixel - viewport.xy) / viewport.zw * 2.0 - 1.0, 0.0, 1.0);
  uv = corner;  // the view was drawn upright in GL's orientation
}
