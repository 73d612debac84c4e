#pragma once
// Cameras: the study's benchmark pose (SPEC G4) and an orbit around an object.
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "common/topology.hpp"

namespace inkwire {

struct Camera {
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
  float near_plane = 0.1f;
  float far_plane = 100.0f;

  glm::mat4 view() const;
  // `fov_y_degrees` spans the viewport's height where it is at least as wide as high, and its
  // width where it is narrower (fit_scale): a portrait viewport (a phone held upright) shows what
  // a square one does, with more above and below, instead of cutting the sides off.
  glm::mat4 projection(float aspect) const;
};

// How much a picture of `picture_aspect` (width / height) drawn at a viewport's full height is
// scaled so it fits the viewport's width as well: 1 where the viewport (of `viewport_aspect`)
// is at least as wide as the picture, less where it is narrower. The turntable's photos
// (letterboxed) and a scene's field of view (as a square picture) both follow it; the browser's
// element keeps the same rule (client/web/common/framing.js, pinned by warp-vectors.json).
float fit_scale(float viewport_aspect, float picture_aspect);

// The study's viewer: at (12.73, 17.85, 12.52) with orientation (w,x,y,z) =
// (0.866, -0.091, 0.490, 0.051). Read as a camera-to-world rotation, that quaternion leaves
// the object (at the origin) 34 degrees below the view axis, outside a 45-degree field of view,
// so the source's convention must have differed. We keep the position and the quaternion's up
// vector (its roll) and aim at the origin, which is what the study's figures show.
Camera thesis_camera();

// A camera on a sphere around `bounds`: azimuth about +Y from +Z, elevation above the XZ plane,
// distance in bounding-box diagonals from the centre.
Camera orbit_camera(const Bounds& bounds, float azimuth_degrees, float elevation_degrees, float distance_diagonals);

// Sessions share one scene space: every object centred and scaled to this bounding-box diagonal,
// so camera poses mean the same on every client whatever the mesh's own units.
inline constexpr float kSceneDiagonal = 10.0f;
// orbit_camera() around the centre of the scene space.
Camera scene_orbit_camera(float azimuth_degrees, float elevation_degrees, float distance_diagonals);

// The orbit angles (degrees) and distance (in kSceneDiagonal) of a camera at `position` looking at
// `target`: what scene_orbit_camera() makes, turned back.
struct SceneOrbit {
  float azimuth, elevation, distance;
};
SceneOrbit scene_orbit_of(const glm::vec3& position, const glm::vec3& target);

// The camera of a session's pose (position, target, up, vertical field of view) in the scene
// space: near and far planes hug an object of kSceneDiagonal at the origin.
Camera scene_camera(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float fov_y_degrees);

// A directional light for a camera: from above-left of the viewer, as a unit vector pointing
// from the surface toward the light, in world space.
glm::vec3 default_light_direction(const Camera& camera);

// A session's object pose (translation, rotation, uniform scale) as the model matrix: the one
// rule for the native client and the browser's module alike.
glm::mat4 pose_matrix(const glm::vec3& translation, const glm::quat& rotation, float scale);

}  // namespace inkwire
