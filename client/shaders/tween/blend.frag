#version 450 core
// The weighted sum of the samples' (premultiplied) colours, each read at its own position.
in vec2 uv[SAMPLES];
uniform sampler2D samples[SAMPLES];
uniform vec3 weights;
out vec4 colour;
void main() {
  colour = vec4(0.0);
  for (int k = 0; k < SAMPLES; ++k) colour += weights[k] * texture(samples[k], uv[k]);
}
