#include "common/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace inkwire {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
  const float half = std::atan(std::tan(glm::radians(fov_y_degrees) / 2.0f) / fit_scale(aspect, 1.0f));
  return glm::perspective(2.0f * half, aspect, near_plane, far_plane);
}

float fit_scale(float viewport_aspect, float picture_aspect) {
  if (!(viewport_aspect > 0.0f) || !(picture_aspect > 0.0f)) return 1.0f;
  return std::min(1.0f, viewport_aspect / picture_aspect);
}

Camera thesis_camera() {
  const glm::quat orientation = glm::normalize(glm::quat(0.866f, -0.091f, 0.490f, 0.051f));
  Camera c;
  c.position = {12.73f, 17.85f, 12.52f};
  c.target = {0.0f, 0.0f, 0.0f};
  c.up = orientation * glm::vec3(0.0f, 1.0f, 0.0f);
  c.near_plane = 1.0f;
  c.far_plane = 100.0f;
  return c;
}

Camera orbit_camera(const Bounds& bounds, float azimuth_degrees, float elevation_degrees, float distance_diagonals) {
  const float az = glm::radians(azimuth_degrees);
  const float el = glm::radians(std::clamp(elevation_degrees, -89.0f, 89.0f));
  const float diagonal = std::max(bounds.diagonal(), 1e-6f);
  const float distance = distance_diagonals * diagonal;
  Camera c;
  c.target = bounds.centre();
  c.position = c.target + distance * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  c.near_plane = std::max(distance - diagonal, distance * 0.02f);
  c.far_plane = distance + diagonal;
  return c;
}

Camera scene_orbit_camera(float azimuth_degrees, float elevation_degrees, float distance_diagonals) {
  const float h = kSceneDiagonal / (2.0f * std::sqrt(3.0f));
  return orbit_camera(Bounds{glm::vec3(-h), glm::vec3(h)}, azimuth_degrees, elevation_degrees, distance_diagonals);
}

SceneOrbit scene_orbit_of(const glm::vec3& position, const glm::vec3& target) {
  const glm::vec3 d = position - target;
  return {glm::degrees(std::atan2(d.x, d.z)), glm::degrees(std::asin(std::clamp(d.y / std::max(glm::length(d), 1e-6f), -1.0f, 1.0f))),
          glm::length(d) / kSceneDiagonal};
}

Camera scene_camera(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float fov_y_degrees) {
  Camera c;
  c.position = position;
  c.target = target;
  c.up = up;
  c.fov_y_degrees = fov_y_degrees;
  const float distance = glm::length(position);
  c.near_plane = std::max(distance - kSceneDiagonal, std::max(distance * 0.02f, 0.01f));
  c.far_plane = distance + kSceneDiagonal;
  return c;
}

glm::vec3 default_light_direction(const Camera& camera) {
  const glm::mat4 view_to_world = glm::inverse(camera.view());
  return glm::normalize(glm::vec3(view_to_world * glm::vec4(-0.4f, 0.6f, 0.7f, 0.0f)));
}

glm::mat4 pose_matrix(const glm::vec3& translation, const glm::quat& rotation, float scale) {
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), glm::vec3(scale));
}

}  // namespace inkwire
