// The web-scene suite's first platform reference: a lit sphere turning about its vertical axis, the
// least GL a frame can be (no #version line: the native harness and the page put their own first).
layout(location = 0) in vec3 position;
uniform vec2 turn;  // cos and sin of the frame's angle
out float lit;
void main() {
  vec3 p = vec3(turn.x * position.x + turn.y * position.z, position.y, -turn.y * position.x + turn.x * position.z);
  lit = 0.2 + 0.8 * max(dot(normalize(position), vec3(0.3, 0.5, 0.8)), 0.0);
  gl_Position = vec4(p * 0.8, 1.0);
}
