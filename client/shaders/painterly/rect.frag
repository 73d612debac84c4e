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
  vec4 texel = texture(image, image_uv);
  vec3 rgb = premultiplied ? texel.rgb / max(texel.a, 1.0 / 255.0) : texel.rgb;
  colour = vec4(rgb, opacity * texture(matte, image_uv).a);
}
