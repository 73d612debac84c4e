// Charcoal rubbed along the outline on the shadow side: strongest at the outline, fading over
// the surface's turn toward the eye; only where the light does not reach; broken a little by
// the paper's tooth, less than a stroke (rubbing pushes pigment into the valleys).
in vec3 surface_normal;
in vec3 to_eye;
uniform vec3 light_object;
uniform float smudge;
uniform vec3 ink_colour;
uniform sampler2D tooth;
uniform vec2 tooth_size;
out vec4 colour;
void main() {
  vec3 n = normalize(surface_normal);
  float facing = abs(dot(n, normalize(to_eye)));
  // A sphere's rim band where N.V < 0.3 is under 5% of its radius: the tone fades over the
  // whole turn instead, most of it in the outer third.
  float near_outline = (1.0 - facing) * (1.0 - facing);
  float in_shadow = 1.0 - smoothstep(-0.1, 0.7, dot(n, light_object));
  float t = texture(tooth, gl_FragCoord.xy / tooth_size).r;
  colour = vec4(ink_colour, smudge * near_outline * in_shadow * mix(0.55, 1.0, t));
}
