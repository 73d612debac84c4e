#include "server/products/turntable_camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace inkwire {

glm::vec3 to_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& point) {
  const float azimuth = glm::radians(view.azimuth_deg), elevation = glm::radians(camera.elevations_deg[size_t(view.row)]);
  const glm::vec3 centre(std::sin(azimuth) * std::cos(elevation), std::sin(elevation), std::cos(azimuth) * std::cos(elevation));
  const glm::vec3 ahead = -centre;
  const glm::vec3 right = glm::normalize(glm::cross(ahead, glm::vec3(0, 1, 0)));
  const glm::vec3 down = glm::cross(ahead, right);
  const glm::vec3 d = point - centre;
  return {glm::dot(d, right), glm::dot(d, down), glm::dot(d, ahead)};
}

glm::vec2 to_pixel(const TurntableCamera& camera, const glm::vec3& in_camera) {
  return {camera.axis_x + camera.focal_px * in_camera.x / in_camera.z, 0.5f * float(camera.height) + camera.focal_px * in_camera.y / in_camera.z};
}

}  // namespace inkwire
