#version 450 core
// The brush texture shades the paint (bristle streaks) and says where paint lies; the stencil
// (the object's matte) keeps every brush on the object.
in vec2 shape_uv;
flat in float shape_layer;
flat in vec4 brush_paint;
uniform sampler2DArray shapes;
out vec4 colour;
void main() {
  vec4 shape = texture(shapes, vec3(shape_uv, shape_layer));
  colour = vec4(brush_paint.rgb * shape.rgb, brush_paint.a * shape.a);
}
