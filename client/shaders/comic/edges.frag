// An outline line in its colour, faded at its edges by coverage.
flat in vec3 edge_colour;
out vec4 colour;
#include "common/wide_line_coverage.glsl"
void main() { colour = vec4(edge_colour, wide_line_coverage()); }
