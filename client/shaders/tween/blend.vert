// A view between samples in one pass (SPEC T3/T4): the control-point mesh drawn at the view's
// positions, each vertex also carrying where it lies in every contributing sample, so the
// fragment reads all of them at once instead of one pass per sample. Positions are image
// pixels, y down. SAMPLES (1-3) is prepended.
layout(location = 0) in vec2 position0;
layout(location = 1) in vec2 position1;
layout(location = 2) in vec2 position2;
uniform vec3 position_weights;   // the view's place on the path or in the triangle
uniform ivec3 source;            // which stored position lies in sample k's image
uniform vec2 sample_size[SAMPLES];  // each image's size (may be larger than the view: atlases)
uniform vec4 to_clip;            // clip.xy = pixel * to_clip.xy + to_clip.zw
uniform float depth;
out vec2 uv[SAMPLES];

vec2 stored(int slot) { return slot == 0 ? position0 : (slot == 1 ? position1 : position2); }

void main() {
  vec2 p = position_weights.x * position0 + position_weights.y * position1 + position_weights.z * position2;
  for (int k = 0; k < SAMPLES; ++k) uv[k] = stored(source[k]) / sample_size[k];  // v = 0 is the top row
  gl_Position = vec4(p * to_clip.xy + to_clip.zw, depth, 1.0);
}
