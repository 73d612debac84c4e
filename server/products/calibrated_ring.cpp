#include "server/products/calibrated_ring.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <opencv2/core.hpp>

#include "common/error.hpp"

namespace inkwire {

namespace {

glm::vec3 camera_centre(const RingCamera& c) { return -glm::transpose(c.r) * c.t; }

}  // namespace

RingFrame ring_frame(const PhotoRing& ring) {
  const std::vector<glm::vec3>& directions = ring.directions;
  glm::vec3 turn(0.0f), mean(0.0f);
  for (size_t i = 0; i + 1 < directions.size(); ++i) turn += glm::cross(directions[i], directions[i + 1]);
  if (glm::length(turn) < 1e-6f) throw Error("the calibrated cameras do not go round the object");
  for (const glm::vec3& d : directions) mean += d / float(directions.size());
  cv::Matx33d spread = cv::Matx33d::zeros();
  for (const glm::vec3& d : directions) {
    const cv::Vec3d o(d.x - mean.x, d.y - mean.y, d.z - mean.z);
    spread += o * o.t();
  }
  cv::Mat values, vectors;
  cv::eigen(cv::Mat(spread), values, vectors);  // descending: the last is the plane's normal
  RingFrame f;
  f.y = glm::vec3(float(vectors.at<double>(2, 0)), float(vectors.at<double>(2, 1)), float(vectors.at<double>(2, 2)));
  if (glm::dot(f.y, turn) < 0.0f) f.y = -f.y;
  // Where the cameras' sights meet: the point nearest every optical axis, by least squares.
  cv::Matx33d normal = cv::Matx33d::zeros();
  cv::Vec3d right(0, 0, 0);
  glm::vec3 centres(0.0f);
  for (size_t i = 0; i < ring.cameras.size(); ++i) {
    const glm::vec3 c = camera_centre(ring.cameras[i]);
    const cv::Vec3d centre(c.x, c.y, c.z), sight(directions[i].x, directions[i].y, directions[i].z);
    const cv::Matx33d across = cv::Matx33d::eye() - sight * sight.t();
    normal += across, right += across * centre, centres += c / float(ring.cameras.size());
  }
  cv::Vec3d object;
  if (cv::solve(cv::Mat(normal), cv::Mat(right), object)) {
    f.object = glm::vec3(float(object[0]), float(object[1]), float(object[2]));
    if (glm::dot(f.y, centres - f.object) < 0.0f) f.y = -f.y;
  } else {
    f.object = centres - glm::dot(centres, f.y) * f.y;  // the cameras' sights are parallel: no object to meet on
  }
  f.distance = 0;
  for (const RingCamera& c : ring.cameras) f.distance += glm::length(camera_centre(c) - f.object) / float(ring.cameras.size());
  if (!(f.distance > 0.0f)) throw Error("the calibrated cameras stand where the object is");
  f.z = glm::normalize(directions[0] - glm::dot(directions[0], f.y) * f.y);
  f.x = glm::cross(f.y, f.z);
  for (const glm::vec3& d : directions) f.directions.push_back(glm::normalize(f.in_frame(d)));
  return f;
}

namespace {

// Camera `c` of `frame` as a pose for a photo stored `size` pixels (turned upright from the frame
// its calibration describes: the turn that brings the ring's up to the picture's up) and shown at
// `shown` pixels with the principal point at its middle row and `axis_x`. A principal point off
// that place is folded into the pose as the small turn that brings it there.
ViewPose calibrated_pose(const RingFrame& frame, const RingCamera& c, glm::ivec2 size, glm::ivec2 shown, float focal_shown, float axis_x) {
  const glm::vec3 right = frame.in_frame(glm::vec3(c.r[0][0], c.r[1][0], c.r[2][0])), down = frame.in_frame(glm::vec3(c.r[0][1], c.r[1][1], c.r[2][1])),
                  ahead = frame.in_frame(glm::vec3(c.r[0][2], c.r[1][2], c.r[2][2]));
  // The picture's right and down, and the principal point, for each quarter turn calibrated_pixel
  // undoes; the one whose up is the ring's up.
  const float w = float(size.x - 1), h = float(size.y - 1), cx = c.k[2][0], cy = c.k[2][1];
  const std::array<std::array<glm::vec3, 2>, 4> axes = {{{right, down}, {down, -right}, {-right, -down}, {-down, right}}};
  const std::array<glm::vec2, 4> principal = {glm::vec2(cx, cy), glm::vec2(cy, h - cx), glm::vec2(w - cx, h - cy), glm::vec2(w - cy, cx)};
  int turn = 0;
  for (int q = 1; q < 4; ++q)
    if (-axes[size_t(q)][1].y > -axes[size_t(turn)][1].y) turn = q;
  ViewPose pose;
  pose.right = axes[size_t(turn)][0], pose.down = axes[size_t(turn)][1], pose.ahead = ahead;
  const glm::vec2 p = principal[size_t(turn)] * glm::vec2(shown) / glm::vec2(size), middle(axis_x, 0.5f * float(shown.y));
  pose.ahead = glm::normalize(pose.ahead + ((middle.x - p.x) * pose.right + (middle.y - p.y) * pose.down) / focal_shown);
  pose.right = glm::normalize(pose.right - glm::dot(pose.right, pose.ahead) * pose.ahead);
  pose.down = glm::cross(pose.ahead, pose.right);
  pose.centre = frame.in_frame(camera_centre(c) - frame.object) / frame.distance;
  return pose;
}

}  // namespace

CalibratedCamera calibrated_camera(const RingFrame& frame, const std::vector<RingCamera>& cameras, glm::ivec2 stored, glm::ivec2 shown) {
  CalibratedCamera out;
  for (size_t i = 0; i < cameras.size(); ++i) {
    const glm::mat3& k = cameras[i].k;
    out.focal_px += 0.5f * (k[0][0] + k[1][1]) * float(shown.x) / float(stored.x) / float(cameras.size());
  }
  for (const RingCamera& c : cameras) {
    out.poses.push_back(calibrated_pose(frame, c, stored, shown, out.focal_px, 0.5f * float(shown.x)));
    out.elevation_deg += glm::degrees(std::asin(std::clamp(-out.poses.back().ahead.y, -1.0f, 1.0f))) / float(cameras.size());
  }
  return out;
}

}  // namespace inkwire
