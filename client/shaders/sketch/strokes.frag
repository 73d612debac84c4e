// Ink of the sketched lines; with WIDE_LINE (strokes.vert) faded at the edges by coverage.
in float stroke_opacity;
uniform vec4 ink;
out vec4 colour;
#ifdef WIDE_LINE
#include "common/wide_line_coverage.glsl"
#endif
void main() {
#ifdef WIDE_LINE
  colour = vec4(ink.rgb, ink.a * stroke_opacity * wide_line_coverage());
#else
  colour = vec4(ink.rgb, ink.a * stroke_opacity);
#endif
}
