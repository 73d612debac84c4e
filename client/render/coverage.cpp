#include "client/render/coverage.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "client/render/backdrop.hpp"
#include "common/error.hpp"

namespace inkwire {

double measure_coverage(Renderer& renderer, const FrameState& frame, const Canvas& canvas) {
  canvas.bind();
  const Backdrop none(BackdropSpec::parse("none"));
  none.draw();
  FrameState over_none = frame;
  over_none.backdrop = &none;
  renderer.draw(over_none);
  const Image img = canvas.read();
  size_t covered = 0;
  for (size_t i = 3; i < img.pixels.size(); i += 4) covered += img.pixels[i] > 0;
  return double(covered) / (double(img.width) * img.height);
}

float fit_scale_for_coverage(Renderer& renderer, FrameState frame, const Canvas& canvas, double target) {
  const glm::mat4 base = frame.model;
  float scale = 1.0f;
  for (int i = 0; i < 6; ++i) {
    frame.model = base * glm::scale(glm::mat4(1.0f), glm::vec3(scale));
    const double coverage = measure_coverage(renderer, frame, canvas);
    if (coverage <= 0.0) throw Error("object is not visible from this pose: cannot fit its coverage");
    if (std::abs(coverage - target) < 0.002) break;
    scale *= float(std::sqrt(target / coverage));  // area grows with the square of the scale
  }
  return scale;
}

}  // namespace inkwire
