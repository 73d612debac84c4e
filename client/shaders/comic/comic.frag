// The triangle's flat base colour (C7), times the base texture (C9) where TEXTURED, shaded by
// the map.
in vec2 shade_coord;
in vec2 texcoord;
flat in vec4 triangle_colour;

uniform sampler2D shade_map;  // extended: the shade-map image; else one row (Texture::lookup_row)
#ifdef TEXTURED
uniform sampler2D base_texture;
#endif
uniform float shadow_saturation;  // studied cartoons raise saturation in shadow by ~12%

out vec4 colour;

vec3 apply_shade(vec3 base, vec3 texel) {
  // Below mid-grey a texel multiplies the colour; above, it lifts it toward white.
  vec3 multiplied = base * min(texel * 2.0, vec3(1.0));
  return mix(multiplied, vec3(1.0), max(texel * 2.0 - 1.0, vec3(0.0)));
}

void main() {
  vec3 base = triangle_colour.rgb;
#ifdef TEXTURED
  base *= texture(base_texture, texcoord).rgb;
#endif
#ifdef EXTENDED
  // Shade map images put R.V = 0 on their bottom row; textures start at the image's top row.
  vec3 texel = texture(shade_map, vec2(shade_coord.x, 1.0 - shade_coord.y)).rgb;
#else
  vec3 texel = texture(shade_map, vec2(shade_coord.x, 0.5)).rgb;
#endif
  vec3 shaded = apply_shade(base, texel);
  float darkening = clamp(1.0 - 2.0 * dot(texel, vec3(1.0 / 3.0)), 0.0, 1.0);
  float grey = dot(shaded, vec3(0.299, 0.587, 0.114));
  shaded = clamp(mix(vec3(grey), shaded, 1.0 + shadow_saturation * min(darkening / 0.24, 1.0)), 0.0, 1.0);
  colour = vec4(shaded, 1.0);
}
