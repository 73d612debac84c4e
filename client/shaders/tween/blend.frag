// The weighted sum of the samples' (premultiplied) colours, each read at its own position.
//
// With MATTE (SPEC T14) the samples are matte textures (make_matte_texture): colour bled past
// the outline, and alpha the signed distance to the sample's outline (0.5 on it, MATTE_RANGE
// pixels to either end). The view's outline is where the weighted distances cross zero, so it
// moves from one sample's outline to the other's as a single edge instead of two half-faded
// ones; the colour comes from the samples that see the object at this pixel.
//
// A sample's say that a pixel is object counts at most INSIDE_SAY pixels deep, while its say that
// it is background counts to the full range: the pixel is object where the samples agree it is.
// Near an outline (distances of a pixel or two) this is the plain weighted crossing; where one
// sample sees deep object and the other background (a gap between a mirror and the cab that the
// other sample sees the flank through), background wins unless its sample's weight is small.
// On the truck at 512 px, 24 samples: worst matte IoU 0.966 -> 0.972 (docs/benchmarks.md).
// Under the object lies the floor layer (SPEC T16: a product's shadow), what the samples show
// further than BLEED + 1 pixels outside their outline, warped with them and blended.
in vec2 uv[SAMPLES];
uniform sampler2D samples[SAMPLES];
uniform vec3 weights;
out vec4 colour;
const float INSIDE_SAY = 2.0;
const float FLOOR_NOISE = 0.03;
// Sample k's texel at its position: GLSL 3.30 and ES 3.00 index sampler arrays only by constants.
vec4 sample_texel(int k) {
#if SAMPLES > 2
  if (k == 2) return texture(samples[2], uv[2]);
#endif
#if SAMPLES > 1
  if (k == 1) return texture(samples[1], uv[1]);
#endif
  return texture(samples[0], uv[0]);
}
void main() {
#ifdef MATTE
  float distance = 0.0, total = 0.0, floor_total = 0.0;
  vec3 rgb = vec3(0.0), floor_rgb = vec3(0.0);
  for (int k = 0; k < SAMPLES; ++k) {
    vec4 texel = sample_texel(k);
    float d = (texel.a - 0.5) * (2.0 * MATTE_RANGE);
    distance += weights[k] * min(d, INSIDE_SAY);
    // A sample that sees background here lends its (bled) colour only where no other sees object.
    float w = weights[k] * (0.01 + clamp(d + 0.5, 0.0, 1.0));
    rgb += w * texel.rgb;
    total += w;
    // Past the bleed its colour is the floor layer on white.
    float f = weights[k] * clamp(-(d + BLEED), 0.0, 1.0);
    floor_rgb += f * texel.rgb;
    floor_total += f;
  }
  float coverage = clamp(distance + 0.5, 0.0, 1.0);
  // The floor layer premultiplied: as opaque as its darkest channel is dark, so laid on white it
  // is the photo's shadow again, and on any other backdrop a shadow of the same depth.
  vec3 on_white = floor_total > 0.0 ? floor_rgb / floor_total : vec3(1.0);
  float floor_alpha = 1.0 - min(on_white.r, min(on_white.g, on_white.b));
  // A JPEG rings a few levels round an outline: so faint a floor is none.
  float kept = max(floor_alpha - FLOOR_NOISE, 0.0) / max(floor_alpha, 1e-6);
  colour = vec4(rgb / max(total, 1e-6) * coverage, coverage) + (1.0 - coverage) * kept * vec4(on_white - vec3(1.0 - floor_alpha), floor_alpha);
#else
  colour = vec4(0.0);
  for (int k = 0; k < SAMPLES; ++k) colour += weights[k] * sample_texel(k);
#endif
}
