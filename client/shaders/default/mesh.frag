// Smooth shading, times the base texture where TEXTURED.
in vec4 shaded;
in vec2 texcoord;
#ifdef TEXTURED
uniform sampler2D base_texture;
#endif
out vec4 colour;
void main() {
#ifdef TEXTURED
  colour = shaded * texture(base_texture, texcoord);
#else
  colour = shaded;
#endif
  colour.a = 1.0;
}
