// A depth texture's 24 bits as colour, red the highest byte, for reading depth back where only
// colour can be read (WebGL2): Canvas::read_depth().
uniform sampler2D depth;
out vec4 colour;
void main() {
  // In single precision 1.0 * 16777215 + 0.5 rounds up to 2^24: held to the 24 bits.
  uint bits = min(uint(texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r * 16777215.0 + 0.5), 16777215u);
  colour = vec4(float(bits >> 16u), float((bits >> 8u) & 255u), float(bits & 255u), 255.0) / 255.0;
}
