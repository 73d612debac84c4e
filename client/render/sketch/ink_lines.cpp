#include "client/render/sketch/ink_lines.hpp"

namespace inkwire {

std::vector<ParamSpec> InkLineStyle::params() {
  return {
      float_param("boil_hz", "12", 0, 120, "how often per second of animation the wobble changes (0 = never)"),
      float_param("wobble", "0.04", 0, 0.5, "sideways wobble as a fraction of the stroke's length..."),
      float_param("wobble_clamp", "0.006", 0, 0.1, "...at most this fraction of the bounding-box diagonal"),
      float_param("segment", "0.02", 0.001, 1, "wobble detail: longest straight piece, fraction of the diagonal"),
      float_param("line_width", "1.6", 0.5, 8, "stroke width in pixels"),
      colour_param("ink", "#26262a", "stroke colour"),
      float_param("ink_opacity", "0.8", 0, 1, "stroke opacity (overlapping strokes darken)"),
  };
}

void InkLineStyle::configure(const StyleParams& p) {
  boil_hz = p.get_float("boil_hz");
  wobble = p.get_float("wobble");
  wobble_clamp = p.get_float("wobble_clamp");
  segment = p.get_float("segment");
  line_width = p.get_float("line_width");
  ink = glm::vec4(p.get_colour("ink"), p.get_float("ink_opacity"));
}

PerturbOptions InkLineStyle::perturb_for(float diagonal) const {
  PerturbOptions o;
  o.amplitude_ratio = wobble;
  o.amplitude_clamp = wobble_clamp * diagonal;
  o.max_segment = segment * diagonal;
  return o;
}

}  // namespace inkwire
