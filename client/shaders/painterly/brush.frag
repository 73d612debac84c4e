#version 450 core
// The brush texture shades the paint (bristle streaks) and says where paint lies; the matte
// keeps every brush on the object.
in vec2 shape_uv;
in vec2 matte_uv;
flat in float shape_layer;
flat in vec4 brush_paint;
uniform sampler2DArray shapes;
uniform sampler2D matte;
out vec4 colour;
void main() {
  vec4 shape = texture(shapes, vec3(shape_uv, shape_layer));
  float inside = texture(matte, matte_uv).a;
  colour = vec4(brush_paint.rgb * shape.rgb, brush_paint.a * shape.a * inside);
}
