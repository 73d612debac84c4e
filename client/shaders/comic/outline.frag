// Black, or the triangle's own colour darkened (coloured silhouette, C8); faded at the line's
// edges by coverage.
flat in vec4 triangle_colour;
uniform bool coloured;
uniform float darkening;
uniform vec3 ink;
out vec4 colour;
#include "common/wide_line_coverage.glsl"
void main() { colour = vec4(coloured ? triangle_colour.rgb * (1.0 - darkening) : ink, wide_line_coverage()); }
