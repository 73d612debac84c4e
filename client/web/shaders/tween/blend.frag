#version 300 es
// client/shaders/tween/blend.frag for WebGL2. Without MATTE: the weighted sum of the samples'
// (premultiplied) colours. With MATTE, composing by mattes: the samples are
// matte textures (matte_sample.js): colour bled past the outline, alpha the signed distance to
// the sample's outline. The view's outline is where the weighted distances cross zero, a
// sample's say that a pixel is object counting at most INSIDE_SAY pixels deep (so the pixel is
// object where the samples agree it is); the colour comes from the samples that see the object
// at the pixel; under it the floor layer (a shadow: the samples' colours further than BLEED + 1
// pixels outside their outline). Premultiplied output.
// Samplers are indexed by constants only (GLSL ES 3.00), so the samples are unrolled.
precision highp float;
in vec2 uv0;
in vec2 uv1;
in vec2 uv2;
uniform sampler2D sample0;
uniform sampler2D sample1;
uniform sampler2D sample2;
uniform vec3 weights;
out vec4 colour;

#ifdef MATTE
const float INSIDE_SAY = 2.0;
const float FLOOR_NOISE = 0.03;
float distance_sum = 0.0, total = 0.0, floor_total = 0.0;
vec3 rgb = vec3(0.0), floor_rgb = vec3(0.0);

void add(vec4 texel, float weight) {
  float d = (texel.a - 0.5) * (2.0 * MATTE_RANGE);
  distance_sum += weight * min(d, INSIDE_SAY);
  float w = weight * (0.01 + clamp(d + 0.5, 0.0, 1.0));
  rgb += w * texel.rgb;
  total += w;
  float f = weight * clamp(-(d + BLEED), 0.0, 1.0);
  floor_rgb += f * texel.rgb;
  floor_total += f;
}
#endif

void main() {
#ifdef MATTE
  add(texture(sample0, uv0), weights.x);
#if SAMPLES > 1
  add(texture(sample1, uv1), weights.y);
#endif
#if SAMPLES > 2
  add(texture(sample2, uv2), weights.z);
#endif
  float coverage = clamp(distance_sum + 0.5, 0.0, 1.0);
  vec3 on_white = floor_total > 0.0 ? floor_rgb / floor_total : vec3(1.0);
  float floor_alpha = 1.0 - min(on_white.r, min(on_white.g, on_white.b));
  // A JPEG rings a few levels round an outline: so faint a floor is none.
  float kept = max(floor_alpha - FLOOR_NOISE, 0.0) / max(floor_alpha, 1e-6);
  colour = vec4(rgb / max(total, 1e-6) * coverage, coverage) + (1.0 - coverage) * kept * vec4(on_white - vec3(1.0 - floor_alpha), floor_alpha);
#else
  colour = weights.x * texture(sample0, uv0);
#if SAMPLES > 1
  colour += weights.y * texture(sample1, uv1);
#endif
#if SAMPLES > 2
  colour += weights.z * texture(sample2, uv2);
#endif
#endif
}
