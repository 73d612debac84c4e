// Premultiplied colour, blended "over" whatever the target holds (backdrop, other objects).
in vec2 uv;
uniform sampler2D view_image;
out vec4 colour;
void main() {
  colour = texture(view_image, uv);
}
