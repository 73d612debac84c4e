uniform vec4 line_colour;
out vec4 colour;
#include "common/wide_line_coverage.glsl"
void main() { colour = vec4(line_colour.rgb, line_colour.a * wide_line_coverage()); }
