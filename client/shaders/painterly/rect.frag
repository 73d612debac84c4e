#version 450 core
// An image laid over the capture rectangle inside the object's matte: the brushes' base coat
// (premultiplied coarse colours, blurred by linear filtering) or the oil filter's output.
in vec2 image_uv;
uniform sampler2D image;
uniform sampler2D matte;
uniform bool premultiplied;
uniform float opacity;
out vec4 colour;
void main() {
  float inside = texture(matte, image_uv).a;
  // Outside the object nothing is drawn, so the stencil it may write marks the object exactly.
  if (inside < 0.5) discard;
  vec4 texel = texture(image, image_uv);
  vec3 rgb = premultiplied ? texel.rgb / max(texel.a, 1.0 / 255.0) : texel.rgb;
  colour = vec4(rgb, opacity * inside);
}
