// Paper at one texel per pixel, repeating: the grain keeps its scale at any window size.
uniform sampler2D paper;
uniform vec2 paper_size;
out vec4 colour;
void main() {
  colour = vec4(texture(paper, gl_FragCoord.xy / paper_size).rgb, 1.0);
}
