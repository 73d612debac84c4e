#pragma once
// The measurements an expression is chosen from (SPEC F2), taken from 68 landmarks in the
// normalised face frame, so position, size and roll of the head drop out. Lengths are in
// inter-ocular units; eye openness is the eye's height over its width.
#include "common/face/face_shape.hpp"
#include "common/image.hpp"

namespace inkwire {

struct FaceFeatures {
  float brow_raise_left = 0, brow_raise_right = 0;  // brow height above the eye line
  float eye_open_left = 0, eye_open_right = 0;      // lid gap / eye width
  float mouth_open = 0;    // gap between the inner lips
  float mouth_width = 0;   // corner to corner
  float corner_lift = 0;   // corners' height above the outer lips' midline (up is positive)
  float jaw_drop = 0;      // chin below the nose tip
  float brow_inner_raise = 0;  // inner brow ends over the outer ones (sad brows tilt up inside)
  // The spread of grey levels in a box around each eye (as tall as half the eye is wide, so it
  // does not rest on the lids' landmarks): an open eye shows its white and its iris, a shut one
  // skin and lashes. 0 where no frame was given.
  float eye_shade_left = 0, eye_shade_right = 0;
};

// Landmark features; with the frame the landmarks were found in, the eyes' shade too.
FaceFeatures measure_features(const FaceLandmarks& landmarks, const Image* frame = nullptr);

FaceFeatures operator+(const FaceFeatures& a, const FaceFeatures& b);
FaceFeatures operator*(float s, const FaceFeatures& f);

}  // namespace inkwire
