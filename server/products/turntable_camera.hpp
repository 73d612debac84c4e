#pragma once
// The turntable's camera (SPEC T24): one camera, fixed, and an object turning about a vertical
// axis in front of it. In the object's frame (y up, the axis through the origin) the camera stands
// at distance 1 from the origin, at the photo's azimuth round the axis and its row's elevation
// above the turntable's plane, and looks at the origin; the picture's principal point is its
// middle row at the axis's column (the origin is the point of the axis seen at the middle row, so
// a photo's elevation is the camera's tilt down toward the axis). Lengths are in units of that
// distance; pixels are the photos' own.
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace inkwire {

struct TurntableCamera {
  int width = 0, height = 0;
  float focal_px = 0;
  std::vector<float> elevations_deg;  // per row, the lowest first
  float axis_x = 0;                   // the axis's column in the picture (pixels)
};

// A camera placed by a calibration instead of by the turntable (a lab's gantry does not turn about
// one axis exactly): where it stands and its right, down and ahead directions, in the object frame
// and units of the turntable's camera distance. Its picture's middle row and the axis column are
// where `ahead` meets it, as the turntable's.
struct ViewPose {
  glm::vec3 centre{0.0f}, right{1, 0, 0}, down{0, -1, 0}, ahead{0, 0, -1};
};

// Where one photo was taken from: its azimuth round the axis and its row, or a calibrated pose.
struct PhotoView {
  float azimuth_deg = 0;
  int row = 0;
  std::optional<ViewPose> pose;  // when set, the camera stands there instead
};

// The view `t` of the way from `a` to `b` (the shorter way round): between two calibrated poses, a
// pose between them.
PhotoView view_between(const PhotoView& a, const PhotoView& b, float t);

// A point of the object frame in the camera's frame of `view`: x right, y down, z ahead (depth).
glm::vec3 to_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& point);
// A point of the camera's frame of `view` back in the object frame.
glm::vec3 from_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& in_camera);
// Where the point `depth` ahead of `from`'s camera at `pixel` lies in `to`'s camera frame.
glm::vec3 seen_from(const TurntableCamera& camera, const PhotoView& from, const glm::vec2& pixel, float depth, const PhotoView& to);
// The pixel of a point in front of the camera (z > 0).
glm::vec2 to_pixel(const TurntableCamera& camera, const glm::vec3& in_camera);

}  // namespace inkwire
