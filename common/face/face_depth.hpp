#pragma once
// A depth for the face's 68 landmarks (SPEC F20), so a face drawn from one frontal photo can turn:
// each landmark of the member's neutral photo keeps its place in the photo's face frame and gets
// a depth, z towards the camera in inter-ocular units, 0 at the plane of the eye centres.
//
// The depth is a generic adult face's, fitted to the member's own landmarks where they say
// something about it. The features' depths (brows, eyes, nose, lips) are an average face's from
// anthropometric norms (Farkas' head and face measurements: the nose tip about 42 mm in front of
// the eye centres and the subnasal point 24 mm, the mouth corners level with the eyes, the outer
// eye corners 10 mm behind them), over an eye distance of 63 mm. The jaw line is the face's
// outline in a frontal photo, so its depth follows from where it lies: the cheek curves back as
// z = 0.22 - 0.83 x^2 (the chin's depth at the middle, the ears' at the mean face's width; x is
// the member's own contour point in the face frame), so a wide face reaches further back to its
// ears than a narrow one. What it cannot be is one person's face: noses and chins that stand out
// more than the average turn less than they would.
#include <array>

#include "common/face/face_shape.hpp"

namespace inkwire {

// The depth of each landmark of a face whose neutral landmarks, in its own face frame, are
// `face` (to_face(neutral, face_frame(neutral))).
std::array<float, kFaceLandmarks> landmark_depths(const FaceLandmarks& face);

// The jaw line's depth at face-frame x (the rule above), for points beside the face too.
float contour_depth(float x);

}  // namespace inkwire
