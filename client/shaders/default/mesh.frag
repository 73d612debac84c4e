#version 450 core
in vec4 shaded;
in vec2 texcoord;
uniform sampler2D base_texture;
uniform bool textured;
out vec4 colour;
void main() {
  colour = textured ? shaded * texture(base_texture, texcoord) : shaded;
  colour.a = 1.0;
}
