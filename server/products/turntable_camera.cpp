#include "server/products/turntable_camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace inkwire {

namespace {

// The camera of `view`: where it stands and its right, down and ahead directions (object frame).
using Frame = ViewPose;

Frame frame_of(const TurntableCamera& camera, const PhotoView& view) {
  if (view.pose) return *view.pose;
  const float azimuth = glm::radians(view.azimuth_deg), elevation = glm::radians(camera.elevations_deg[size_t(view.row)]);
  Frame f;
  f.centre = glm::vec3(std::sin(azimuth) * std::cos(elevation), std::sin(elevation), std::cos(azimuth) * std::cos(elevation));
  f.ahead = -f.centre;
  f.right = glm::normalize(glm::cross(f.ahead, glm::vec3(0, 1, 0)));
  f.down = glm::cross(f.ahead, f.right);
  return f;
}

}  // namespace

PhotoView view_between(const PhotoView& a, const PhotoView& b, float t) {
  const float turn = std::remainder(b.azimuth_deg - a.azimuth_deg, 360.0f);
  PhotoView out{.azimuth_deg = a.azimuth_deg + t * turn, .row = a.row};
  if (a.pose && b.pose) {
    const auto mix = [t](const glm::vec3& p, const glm::vec3& q) { return (1.0f - t) * p + t * q; };
    ViewPose pose;
    // On the arc between the two cameras, at their distance, looking as they look between.
    pose.centre = glm::normalize(mix(a.pose->centre, b.pose->centre)) * ((1.0f - t) * glm::length(a.pose->centre) + t * glm::length(b.pose->centre));
    pose.ahead = glm::normalize(mix(a.pose->ahead, b.pose->ahead));
    pose.right = glm::normalize(mix(a.pose->right, b.pose->right) - glm::dot(mix(a.pose->right, b.pose->right), pose.ahead) * pose.ahead);
    pose.down = glm::cross(pose.ahead, pose.right);
    out.pose = pose;
  }
  return out;
}

glm::vec3 to_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& point) {
  const Frame f = frame_of(camera, view);
  const glm::vec3 d = point - f.centre;
  return {glm::dot(d, f.right), glm::dot(d, f.down), glm::dot(d, f.ahead)};
}

glm::vec3 from_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& in_camera) {
  const Frame f = frame_of(camera, view);
  return f.centre + in_camera.x * f.right + in_camera.y * f.down + in_camera.z * f.ahead;
}

glm::vec3 seen_from(const TurntableCamera& camera, const PhotoView& from, const glm::vec2& pixel, float depth, const PhotoView& to) {
  const glm::vec3 in_from((pixel.x - camera.axis_x) * depth / camera.focal_px, (pixel.y - 0.5f * float(camera.height)) * depth / camera.focal_px, depth);
  return to_camera(camera, to, from_camera(camera, from, in_from));
}

glm::vec2 to_pixel(const TurntableCamera& camera, const glm::vec3& in_camera) {
  return {camera.axis_x + camera.focal_px * in_camera.x / in_camera.z, 0.5f * float(camera.height) + camera.focal_px * in_camera.y / in_camera.z};
}

}  // namespace inkwire
