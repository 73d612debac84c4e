#pragma once
// A calibrated ring of photos (photo_ring.hpp: a lab's cameras, each with its own pose) in the
// turntable's terms (turntable_camera.hpp): the frame the clients' orbit uses, the focal length
// and elevation the shape is checked against, and each camera's pose to carve the shape under.
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "server/products/turntable_camera.hpp"
#include "server/tween/photo_ring.hpp"

namespace inkwire {

// A calibrated ring in the frame the clients' orbit uses (a lab's world frame is anyone's guess):
// the ring about +Y, the first photo at azimuth 0, the origin where the cameras' sights meet (the
// object) and lengths in units of the cameras' mean distance from it.
struct RingFrame {
  glm::vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};  // the frame's axes in the calibration's world
  glm::vec3 object{0.0f};
  float distance = 1;
  std::vector<glm::vec3> directions;  // per camera, in the calibration's order: unit, from the object toward it
  glm::vec3 in_frame(const glm::vec3& world_direction) const {
    return {glm::dot(world_direction, x), glm::dot(world_direction, y), glm::dot(world_direction, z)};
  }
};

// The ring's axis is the normal of the plane the directions' tips lie in (they go round a cone
// about it), not the sum of their turns: a ring with gaps (templeRing's 35 degrees) tilts that sum
// 5 degrees toward its dense side. Up is the side the cameras stand on, seen from where their
// sights meet: a calibration does not say which way is up, and a turntable's camera looks down.
// Throws inkwire::Error when the cameras do not go round one place.
RingFrame ring_frame(const PhotoRing& ring);

// What a calibration says of a ring's camera in the turntable's terms, for the photos at their
// first level: to carve the shape under, and to check the camera the silhouettes give against.
struct CalibratedCamera {
  float focal_px = 0;           // at the photos' first level
  float elevation_deg = 0;      // the cameras' mean tilt toward the object above the ring's plane
  std::vector<ViewPose> poses;  // per photo, in the folder's order: with the axis column at the picture's middle
};

// `cameras` (of `frame`, in the photos' order) for photos stored `stored` pixels and shown at
// `shown`. A photo stored turned from the frame its calibration describes (templeRing's are
// upright at 480 x 640, calibrated lying) is turned back by the quarter turn that brings the
// ring's up to the picture's up; a principal point off the picture's middle is folded into each
// pose as the small turn that brings it there.
CalibratedCamera calibrated_camera(const RingFrame& frame, const std::vector<RingCamera>& cameras, glm::ivec2 stored, glm::ivec2 shown);

}  // namespace inkwire
