#pragma once
// The hand-drawn ink line the line sketchers share (sketch-recursive, sketch-segments): how
// it wobbles, how often it boils, its width and its ink, as style parameters.
#include <cmath>
#include <vector>

#include <glm/vec4.hpp>

#include "client/render/sketch/perturb.hpp"
#include "common/style_params.hpp"

namespace inkwire {

struct InkLineStyle {
  float boil_hz = 12.0f;
  float wobble = 0.04f;          // sideways, as a fraction of the stroke's length...
  float wobble_clamp = 0.006f;   // ...at most this fraction of the bounding-box diagonal
  float segment = 0.02f;         // longest straight piece, fraction of the diagonal
  float line_width = 1.6f;       // pixels
  glm::vec4 ink{0.15f, 0.15f, 0.16f, 0.8f};

  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params);
  // Perturbation options in the units of an object with this bounding-box diagonal.
  PerturbOptions perturb_for(float diagonal) const;
  // Which randomisation step animation time falls in (floor: negative times work too).
  long boil_step(double time_seconds) const {
    return boil_hz > 0.0f ? long(std::floor(time_seconds * boil_hz)) : 0;
  }
};

}  // namespace inkwire
