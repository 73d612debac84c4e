#pragma once
// The turntable's camera (SPEC T24): one camera, fixed, and an object turning about a vertical
// axis in front of it. In the object's frame (y up, the axis through the origin) the camera stands
// at distance 1 from the origin, at the photo's azimuth round the axis and its row's elevation
// above the turntable's plane, and looks at the origin; the picture's principal point is its
// middle row at the axis's column (the origin is the point of the axis seen at the middle row, so
// a photo's elevation is the camera's tilt down toward the axis). Lengths are in units of that
// distance; pixels are the photos' own.
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

// Where one photo was taken from: its azimuth round the axis and its row.
struct PhotoView {
  float azimuth_deg = 0;
  int row = 0;
};

// A point of the object frame in the camera's frame of `view`: x right, y down, z ahead (depth).
glm::vec3 to_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& point);
// A point of the camera's frame of `view` back in the object frame.
glm::vec3 from_camera(const TurntableCamera& camera, const PhotoView& view, const glm::vec3& in_camera);
// Where the point `depth` ahead of `from`'s camera at `pixel` lies in `to`'s camera frame.
glm::vec3 seen_from(const TurntableCamera& camera, const PhotoView& from, const glm::vec2& pixel, float depth, const PhotoView& to);
// The pixel of a point in front of the camera (z > 0).
glm::vec2 to_pixel(const TurntableCamera& camera, const glm::vec3& in_camera);

}  // namespace inkwire
