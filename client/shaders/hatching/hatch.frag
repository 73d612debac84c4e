// Screen-space hatching: strokes fixed to the screen tile, rotated and scaled; the tone of the
// surface (shade lookup by N.L) picks how many strokes show. One of VOLUME, THRESHOLD or
// neither (one layer per pass) is defined; with UNDER_PAPER or UNDER_COLOUR the surface is
// drawn opaque, the backdrop under its ink, instead of as ink blended over the framebuffer.
uniform mat2 screen_to_tile;  // rotation and repeat scale
uniform float strength;
#if defined(THRESHOLD)
// A texel's ink as two steps: N.L, strength, N.L, strength (N.L in 0..1 for -1..1). A step is
// reached where clamp((2 * its N.L - 1 - N.L) / softness + 0.5) is 1, written here as
// clamp(its N.L * threshold_scale - threshold_offset) with the surface's part from the vertex.
uniform sampler2D tones;
uniform float threshold_scale;
in float threshold_offset;
uniform vec3 ink_colour;
#else
in float n_dot_l;
uniform sampler2D tone_lookup;  // one row: N.L in -1..1 mapped to 0..1 -> tone 0 (paper) .. 1 (darkest)
#if defined(VOLUME)
uniform sampler3D tones;        // depth axis is tone
#else
uniform sampler2DArray tones;   // one layer per pass
uniform float layer;            // this pass's layer
uniform float layer_count;
#endif
#endif
#if defined(UNDER_PAPER)
uniform sampler2D paper;        // as the backdrop draws it
uniform vec2 paper_size;
#elif defined(UNDER_COLOUR)
uniform vec4 under_colour;
#endif
out vec4 colour;
void main() {
  // The strokes lie on the screen: the tile is an affine map of the pixel's window position.
  vec2 tile = screen_to_tile * gl_FragCoord.xy;
#if defined(THRESHOLD)
  // The thresholds were turned from tones into N.L through the shade lookup's inverse when the
  // image was made: a texel's ink shows where the surface is darker than its N.L.
  vec4 steps = texture(tones, tile);
  vec2 reached = clamp(steps.rb * threshold_scale - threshold_offset, 0.0, 1.0);
  vec4 ink = vec4(ink_colour, steps.g * reached.x + (steps.a - steps.g) * reached.y);
#else
  float tone = texture(tone_lookup, vec2(n_dot_l * 0.5 + 0.5, 0.5)).r;
#if defined(VOLUME)
  vec4 ink = texture(tones, vec3(tile, tone));
#else
  // This layer fades in as the tone passes it; the layers nest, so passes add up.
  vec4 ink = texture(tones, vec3(tile, layer));
  ink.a *= clamp(tone * (layer_count - 1.0) - layer + 1.0, 0.0, 1.0);
#endif
#endif
  // What blending the ink over the backdrop would give, written opaque: under + (ink - under) * a.
#if defined(UNDER_PAPER)
  vec4 under = vec4(texture(paper, gl_FragCoord.xy / paper_size).rgb, 1.0);
  colour = mix(under, vec4(ink.rgb, 1.0), ink.a * strength);
#elif defined(UNDER_COLOUR)
  colour = under_colour + ((vec4(ink.rgb, 1.0) - under_colour) * strength) * ink.a;  // the bracket is the same for every pixel
#else
  colour = vec4(ink.rgb, ink.a * strength);
#endif
}
