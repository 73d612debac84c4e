#pragma once
// GLSL's smoothstep on the CPU, for textures the renderers make before drawing (stroke and
// brush shapes): 0 below e0, 1 above e1, a cubic with flat ends between.
#include <algorithm>

namespace inkwire {

inline float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

}  // namespace inkwire
