#version 450 core
// Screen-space hatching: strokes fixed to the screen tile, rotated and scaled; the tone of the
// surface (shade lookup by N.L) picks how many strokes show.
in float n_dot_l;
uniform sampler1D tone_lookup;  // N.L in -1..1 mapped to 0..1 -> tone 0 (paper) .. 1 (darkest)
uniform mat2 screen_to_tile;    // rotation and repeat scale
uniform float strength;
#ifdef VOLUME
uniform sampler3D tones;        // depth axis is tone
#else
uniform sampler2DArray tones;   // one layer per pass
uniform float layer;            // this pass's layer
uniform float layer_count;
#endif
out vec4 colour;
void main() {
  vec2 tile = screen_to_tile * gl_FragCoord.xy;
  float tone = texture(tone_lookup, n_dot_l * 0.5 + 0.5).r;
#ifdef VOLUME
  vec4 ink = texture(tones, vec3(tile, tone));
  colour = vec4(ink.rgb, ink.a * strength);
#else
  // This layer fades in as the tone passes it; the layers nest, so passes add up.
  float visible = clamp(tone * (layer_count - 1.0) - layer + 1.0, 0.0, 1.0);
  vec4 ink = texture(tones, vec3(tile, layer));
  colour = vec4(ink.rgb, ink.a * visible * strength);
#endif
}
