#pragma once
// A head's pose (SPEC F20): how far it is turned from the member's neutral photo, as the server
// reads it (server/face/head_pose.hpp) and the receiver draws it. Angles in degrees, as the wire
// carries them: yaw turns the face towards the image's right, pitch up, roll clockwise on screen.
//
// The face frame (common/face/face_shape.hpp) gets a third axis here, z towards the camera, so a
// face's points have a depth (common/face/face_depth.hpp). The head turns about the top of the
// neck, kNeckPivot: under the ears and behind the face, where the skull sits on the spine, so a
// nod moves the chin more than the brow and a shake slides the face across a head whose outline
// stays about where it was.
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace inkwire {

struct HeadPose {
  float yaw = 0, pitch = 0, roll = 0;
  bool operator==(const HeadPose&) const = default;
};

// Face-frame units (inter-ocular distances): half an eye distance below the eye line, 1.2 behind
// the eye centres (anthropometric norms put the ear canal about 75 mm behind them, 63 mm apart).
inline constexpr glm::vec3 kNeckPivot{0.0f, 0.5f, -1.2f};

// The rotation of `pose` in the face frame: yaw about the vertical axis, then pitch about the
// horizontal one, then roll in the picture's plane.
glm::mat3 rotation_of(const HeadPose& pose);

// A face point (face frame with depth) turned by `pose` about the neck: where it lands, with its
// new depth (nearer the camera is larger). The picture is drawn orthographically: x and y are
// where it shows.
glm::vec3 turned(glm::vec3 point, const glm::mat3& rotation);

// The pose between two, `t` of the way from `a` to `b` (each angle linearly).
HeadPose mix(const HeadPose& a, const HeadPose& b, float t);

}  // namespace inkwire
