#pragma once
// Head pose from the 68 landmarks (SPEC F8, F20: yaw, pitch and roll as a few bytes), against the
// member's own neutral face, so a face that is not symmetric does not read as turned. The head is
// the neutral landmarks with the depth the receiver turns them over (common/face/face_depth.hpp);
// it is turned, scaled and moved until its rigid points (the eye corners and the nose, which
// expressions hardly move) lie where the frame's are, as near as they come (least squares under an
// orthographic camera): what the receiver draws from the pose puts those points where the sender's
// were. Degrees, as the wire carries them (common/face/head_pose.hpp).
#include "common/face/face_shape.hpp"
#include "common/face/head_pose.hpp"

namespace inkwire {

// Yaw and pitch within +-70 degrees (beyond, dlib's frontal model finds no face anyway), roll any.
HeadPose head_pose(const FaceLandmarks& face, const FaceLandmarks& neutral);

}  // namespace inkwire
