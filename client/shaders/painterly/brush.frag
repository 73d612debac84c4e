// The brush texture shades the paint (bristle streaks) and says where paint lies. The medium
// (wash_map.hpp) says how far paint may cross the outline and where wet pigment gathers; with
// SOFT_EDGES its red channel fades the paint across the outline (otherwise the stencil, the
// object's matte, keeps every brush on the object). Each effect is compiled in only when a style
// uses it (SOFT_EDGES, WET_EDGES, GRANULATION, GLAZE): llvmpipe pays for a texture read under
// a uniform branch whether the branch is taken or not.
in vec2 shape_uv;
flat in float shape_layer;
flat in vec4 brush_paint;
uniform sampler2DArray shapes;
uniform sampler2D medium;   // the wash map over the capture rectangle, top row first
uniform vec4 rect;          // the capture rectangle in window pixels
uniform float wet_edges;    // pigment gathered where a wash ends
uniform float granulation;  // pigment settled in the paper's valleys
uniform sampler2D tooth;    // the paper's grain (0 valley .. 1 raised), one texel per pixel
uniform vec2 tooth_size;
out vec4 colour;
void main() {
  vec4 shape = texture(shapes, vec3(shape_uv, shape_layer));
#if defined(SOFT_EDGES) || defined(WET_EDGES)
  vec2 at = (gl_FragCoord.xy - rect.xy) / rect.zw;
  vec4 here = texture(medium, vec2(at.x, 1.0 - at.y));
#endif
  float cover = brush_paint.a * shape.a;
#ifdef SOFT_EDGES
  cover *= here.r;
#endif
  // How thick the pigment lies, relative to the paint as loaded.
  float thickness = 1.0;
#ifdef WET_EDGES
  thickness += 2.5 * wet_edges * here.g;
#endif
#ifdef GRANULATION
  thickness *= 1.0 + granulation * (0.5 - texture(tooth, gl_FragCoord.xy / tooth_size).r) * 1.6;
#endif
  vec3 paint = brush_paint.rgb * shape.rgb;
#ifdef GLAZE
  // Transparent pigment filters what lies under it (blended as destination x source): each
  // layer passes paint^(thickness / LAYERS) of the light, so the paper shows through, washes
  // darken where they overlap, and where the usual few overlap the paint's own colour results.
  const float LAYERS = 2.5;
  colour = vec4(pow(max(paint, vec3(0.02)), vec3(cover * thickness / LAYERS)), clamp(cover, 0.0, 1.0));
#else
  // Opaque paint: thicker is darker and covers more.
  colour = vec4(paint * (1.0 - 0.3 * clamp(thickness - 1.0, 0.0, 1.0)), clamp(cover * thickness, 0.0, 1.0));
#endif
}
