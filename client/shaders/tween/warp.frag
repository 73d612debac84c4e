// One pass's share of the synthesised view: the (premultiplied) sample colour times the
// sample's weight, summed over passes by additive blending.
in vec2 uv;
uniform sampler2D sample_image;
uniform float weight;
out vec4 colour;
void main() {
  colour = weight * texture(sample_image, uv);
}
