#pragma once
// Head pose from the 68 landmarks (SPEC F8: "head pose: yaw/pitch/roll as a few bytes"), against
// the speaker's own neutral face so a face that is not symmetric does not read as turned. Roll
// is the eye line's tilt; yaw and pitch come from how far the nose tip moved from the eyes'
// midpoint, in inter-ocular units, on a head whose nose stands about 0.6 of them in front of
// the eyes. Degrees, as the wire carries them.
#include "common/face/face_shape.hpp"

namespace inkwire {

struct HeadPose {
  float yaw = 0, pitch = 0, roll = 0;  // degrees: turned to the image's right, up, clockwise
};

HeadPose head_pose(const FaceLandmarks& face, const FaceLandmarks& neutral);

}  // namespace inkwire
