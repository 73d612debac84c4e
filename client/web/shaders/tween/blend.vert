#version 300 es
// client/shaders/tween/blend.vert for WebGL2: the control-point mesh drawn at the view's
// positions, each vertex carrying where it lies in every contributing sample. Positions are
// image pixels, y down. SAMPLES (1-3) is prepended.
precision highp float;
layout(location = 0) in vec2 position0;
layout(location = 1) in vec2 position1;
layout(location = 2) in vec2 position2;
uniform vec3 position_weights;  // the view's place on the path or in the triangle
uniform ivec3 source;           // which stored position lies in sample k's image
uniform vec2 sample_size;       // every sample image's size
uniform vec4 to_clip;           // clip.xy = pixel * to_clip.xy + to_clip.zw
out vec2 uv0;
out vec2 uv1;
out vec2 uv2;

vec2 stored(int slot) { return slot == 0 ? position0 : (slot == 1 ? position1 : position2); }

void main() {
  vec2 p = position_weights.x * position0 + position_weights.y * position1 + position_weights.z * position2;
  uv0 = stored(source.x) / sample_size;  // v = 0 is the top row
  uv1 = stored(source.y) / sample_size;
  uv2 = stored(source.z) / sample_size;
  gl_Position = vec4(p * to_clip.xy + to_clip.zw, 0.5, 1.0);
}
