// How much of a pixel a wide line (common/wide_line.glsl) covers: 1 inside its width, falling to
// 0 over the pixel of fringe either side. Included by the fragment shaders that draw lines.
in float line_across;
uniform float line_width;
float wide_line_coverage() { return clamp(0.5 * line_width + 0.5 - abs(line_across), 0.0, 1.0); }
