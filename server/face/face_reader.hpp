#pragma once
// What the server reads of one member's face, picture after picture (SPEC F8, F20-F22): the
// landmarks' features against the member's neutral face, steadied into the expression
// (server/face/expression_selector.hpp) and told as layers (common/face/face_layers.hpp), and the
// head's pose against the neutral face (server/face/head_pose.hpp). A call's analyst keeps one
// per member; inkwire-eval reads clips through the same one, so its figures are the call's.
//
// The expression layer is the selector's code without what the mouth and the eyes say (a laugh
// is a smile with its mouth open); the mouth layer says how far the mouth opens beyond the
// expression's own mouth (a viseme over it) or short of it (back to rest), picture by picture: a
// smile while talking is the smile with the syllables' mouths over it.
//
// The eyes: each eye's openness is its lids' gap against the neutral photo's, picture by
// picture; an eye is drawn shut (0) while the selector reads closed eyes or a wink (steadied over
// pictures, by its rules tuned on the development faces), and both for a blink: both eyes' gaps
// falling together from their recent level, read in the picture itself, since a blink lasts two or
// three pictures at 15 a second, which the selector's smoothing and hold would hide. An open eye's
// openness changes only by a step (kEyeStep), so the landmarks' jitter sends nothing.
#include <deque>
#include <optional>

#include "common/face/face_layers.hpp"
#include "common/image.hpp"
#include "server/face/expression_selector.hpp"

namespace inkwire {

class FaceReader {
 public:
  explicit FaceReader(ExpressionSelector::Options selection = {.calibration_frames = 15}) : selector_(selection) {}

  // The member's neutral photo (its landmarks, and the photo for the eyes' shade): the expression's
  // calibration and the pose's reference. Without one, the first face read is the pose's
  // reference and the first frames calibrate the expression.
  void calibrate(const FaceLandmarks& neutral, const Image* photo = nullptr);

  // One picture's landmarks (in its pixels; nothing when no face was found: the face keeps what
  // it showed) and the picture: the face to show now. The pose is read from `in_frame` when given
  // (the same landmarks in the camera frame the picture was cut from).
  const FaceState& read(const std::optional<FaceLandmarks>& landmarks, const Image* picture = nullptr,
                        const FaceLandmarks* in_frame = nullptr);
  const FaceState& state() const { return state_; }
  // The one code the expression's selector chose (what a single-code stream sends).
  ExpressionState expression() const { return selector_.state(); }

 private:
  // The expression and the mouth from the selector's code and this picture's mouth.
  void read_layers(const FaceFeatures& features, ExpressionState code);
  // Each eye's openness (percent of the neutral's) from this picture's features; `shut_code` the
  // selector's steadied code (eyes closed, a wink).
  void read_eyes(const FaceFeatures& features, Expression shut_code);
  static constexpr float kMouthMargin = 0.05f;  // inter-ocular: the mouth opened this much more or less than the expression's own
  static constexpr int kEyeStep = 12;           // percent
  static constexpr float kBlinkDrop = 0.1f;     // each eye's lids fall this far below their recent level in a blink
  static constexpr size_t kRecent = 9;          // the pictures an eye's recent level is the median of (0.6 s at 15 a second)

  ExpressionSelector selector_;
  std::optional<FaceLandmarks> neutral_;
  FaceState state_;
  std::deque<float> recent_left_, recent_right_, recent_width_;  // the last pictures' eyes' openness, and mouth's width
  std::optional<float> opening_;  // the mouth's opening, lightly steadied
  float mouth_level_ = 0;         // the mouth layer's amount as sent, in steps
};

}  // namespace inkwire
