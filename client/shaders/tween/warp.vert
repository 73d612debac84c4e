// A control-point mesh drawn at a view between samples (SPEC T3/T4): each vertex sits at a
// weighted sum of its positions in the cell's samples (a pair's path weights or a triangle's
// barycentric weights) and reads the bound sample image at its position in that sample.
// Positions are image pixels, y down.
layout(location = 0) in vec2 position0;
layout(location = 1) in vec2 position1;
layout(location = 2) in vec2 position2;
uniform vec3 position_weights;
uniform int source;      // which of the three positions lies in the bound image
uniform vec2 image_size;
uniform vec2 sample_size;  // the bound image's size (may be larger than the view: atlases)
uniform float depth;     // layered passes: each pass a little nearer than the one before
out vec2 uv;
void main() {
  vec2 p = position_weights.x * position0 + position_weights.y * position1 + position_weights.z * position2;
  vec2 s = source == 0 ? position0 : (source == 1 ? position1 : position2);
  uv = s / sample_size;  // images are uploaded top row first: v = 0 is the top
  gl_Position = vec4(p.x / image_size.x * 2.0 - 1.0, 1.0 - p.y / image_size.y * 2.0, depth, 1.0);
}
