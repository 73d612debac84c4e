#pragma once
// The 68-point facial landmark layout (iBUG 300-W, as dlib's shape predictor gives it) and the
// normalised face frame (SPEC F2): origin between the eyes, x along the eye line, y down, one
// unit = the inter-ocular distance. Expression templates and features live in this frame, so
// they do not depend on where the face is, how big it is or how the head is rolled.
//
// "Left" and "right" are the image's: the left eye is the one on the left of the picture.
#include <array>
#include <span>

#include <glm/vec2.hpp>

namespace inkwire {

constexpr int kFaceLandmarks = 68;
using FaceLandmarks = std::array<glm::vec2, kFaceLandmarks>;

namespace face_index {
constexpr int kJawFirst = 0, kChin = 8, kJawLast = 16;
constexpr int kBrowLeftFirst = 17, kBrowLeftLast = 21, kBrowRightFirst = 22, kBrowRightLast = 26;
constexpr int kNoseTip = 33;
// Eyes: outer corner, two upper lid points, inner corner, two lower lid points (clockwise).
constexpr int kEyeLeftFirst = 36, kEyeRightFirst = 42;
constexpr int kMouthLeft = 48, kLipTop = 51, kMouthRight = 54, kLipBottom = 57;
// Inner lips: left corner 60, upper 61-63, right corner 64, lower 65-67 (66 below 62).
constexpr int kInnerLipFirst = 60, kInnerLipLast = 67;
}  // namespace face_index

// Where a face sits in an image: its eye-corner midpoint, eye-line direction and inter-ocular
// distance (between the two eye centres, each the midpoint of its corners: corners do not move
// when the eyes close, so a blink does not shift the frame).
struct FaceFrame {
  glm::vec2 origin{0};
  glm::vec2 axis{1, 0};  // unit vector from the left eye to the right eye
  float scale = 1;       // inter-ocular distance in pixels

  glm::vec2 to_face(glm::vec2 image_point) const;
  glm::vec2 to_image(glm::vec2 face_point) const;
  // Directions (displacements) only: no translation.
  glm::vec2 offset_to_image(glm::vec2 face_offset) const;
};

// Throws inkwire::Error when the eyes coincide (not a face).
FaceFrame face_frame(const FaceLandmarks& landmarks);
FaceLandmarks to_face(const FaceLandmarks& landmarks, const FaceFrame& frame);
FaceLandmarks to_image(const FaceLandmarks& face_points, const FaceFrame& frame);

// Mean distance between corresponding landmarks in inter-ocular units of `reference`'s frame.
float mean_landmark_error(const FaceLandmarks& found, const FaceLandmarks& reference);

}  // namespace inkwire
