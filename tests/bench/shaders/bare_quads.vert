// The web-scene suite's second platform reference: many small quads, as the painterly style's
// brushes are (one per instance, `half_size` pixels each way from its centre).
layout(location = 0) in vec2 centre;  // window pixels
uniform vec2 viewport;
uniform vec2 shift;  // the frame's small move, so no two frames are alike
uniform float half_size;
out vec2 corner;
void main() {
  corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
  gl_Position = vec4((centre + shift + corner * half_size) / viewport * 2.0 - 1.0, 0.0, 1.0);
}
