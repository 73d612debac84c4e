#pragma once
// What the server reads of one member's face, picture after picture (SPEC F8, F20-F22): the
// landmarks' features against the member's neutral face, steadied into the expression
// (server/face/expression_selector.hpp) and told as layers (common/face/face_layers.hpp), and the
// head's pose against the neutral face (server/face/head_pose.hpp). A call's analyst keeps one
// per member; inkwire-eval reads clips through the same one, so its figures are the call's.
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
  ExpressionSelector selector_;
  std::optional<FaceLandmarks> neutral_;
  FaceState state_;
};

}  // namespace inkwire
