// An image laid over the capture rectangle: the brushes' base coat (premultiplied coarse colours,
// blurred by linear filtering) or the oil filter's output inside the object's matte, or a
// painting's glow (premultiplied, added, no matte: light spills over the backdrop).
in vec2 image_uv;
uniform sampler2D image;
uniform sampler2D matte;
uniform int clip;  // 0: by the matte's alpha, hard; 1: by a wash map's red (soft matte); 2: none
uniform bool premultiplied;
uniform float opacity;
out vec4 colour;
void main() {
  vec4 texel = texture(image, image_uv);
  if (clip == 2) {
    colour = vec4(texel.rgb * opacity, max(max(texel.r, texel.g), texel.b) * opacity);
    return;
  }
  float inside = clip == 0 ? texture(matte, image_uv).a : texture(matte, image_uv).r;
  // Where nothing is drawn, the stencil the caller may write is not written either: with the
  // hard clip it then marks the object exactly.
  if (inside < (clip == 0 ? 0.5 : 1.0 / 255.0)) discard;
  vec3 rgb = premultiplied ? texel.rgb / max(texel.a, 1.0 / 255.0) : texel.rgb;
  colour = vec4(rgb, opacity * inside);
}
