#version 450 core
// Black, or the triangle's own colour darkened (coloured silhouette, C8).
layout(std430, binding = 0) readonly buffer TriangleColours { vec4 triangle_colour[]; };
uniform bool coloured;
uniform float darkening;
uniform vec3 ink;
out vec4 colour;
void main() {
  colour = vec4(coloured ? triangle_colour[gl_PrimitiveID].rgb * (1.0 - darkening) : ink, 1.0);
}
