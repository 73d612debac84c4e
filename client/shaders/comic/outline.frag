#version 450 core
// Black, or the triangle's own colour darkened (coloured silhouette, C8).
flat in vec4 triangle_colour;
uniform bool coloured;
uniform float darkening;
uniform vec3 ink;
out vec4 colour;
void main() { colour = vec4(coloured ? triangle_colour.rgb * (1.0 - darkening) : ink, 1.0); }
