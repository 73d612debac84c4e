in vec3 coord;
in float stroke_opacity;
in float along;
in float stroke_pressure;
flat in float run_length;
uniform sampler2DArray strokes;
uniform float strength;
// The paper's tooth (0 valley .. 1 raised), one texel per pixel as the paper backdrop lies: a
// dry medium marks the raised fibres first and fills the valleys as it is pressed harder.
uniform sampler2D tooth;
uniform vec2 tooth_size;
uniform float grain;  // 0: the stroke texture alone; 1: the tooth decides fully
out vec4 colour;
void main() {
  vec4 mark = texture(strokes, coord);
  // Fade in over the first half-width and out over the last: the overrun past each end.
  float ends = clamp(min(along, run_length - along), 0.0, 1.0);
  float reached = 1.0;
  if (grain > 0.0) {
    float fill = mix(0.3, 0.8, stroke_pressure);  // the share of the tooth the stroke reaches
    float t = texture(tooth, gl_FragCoord.xy / tooth_size).r;
    reached = mix(1.0, smoothstep(0.88 - fill, 1.12 - fill, t), grain);
  }
  colour = vec4(mark.rgb, mark.a * stroke_opacity * strength * ends * reached);
}
