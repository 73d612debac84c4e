#include "server/face/face_reader.hpp"

#include "server/face/face_features.hpp"
#include "server/face/head_pose.hpp"

namespace inkwire {

void FaceReader::calibrate(const FaceLandmarks& neutral, const Image* photo) {
  selector_.calibrate(measure_features(neutral, photo));
  neutral_ = neutral;
  state_ = {};
}

const FaceState& FaceReader::read(const std::optional<FaceLandmarks>& landmarks, const Image* picture, const FaceLandmarks* in_frame) {
  const ExpressionState expression = selector_.update(landmarks ? std::optional(measure_features(*landmarks, picture)) : std::nullopt);
  if (!landmarks) return state_;
  const FaceLandmarks& posed = in_frame ? *in_frame : *landmarks;
  if (!neutral_) neutral_ = posed;
  state_.layers = layers_of(expression);
  state_.pose = head_pose(posed, *neutral_);
  return state_;
}

}  // namespace inkwire
