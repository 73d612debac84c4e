#include "server/face/face_coder.hpp"

#include "common/error.hpp"

namespace inkwire {

FaceLandmarks FaceCoder::calibrate(const Image& neutral_photo) {
  analyzer_.reset();
  const auto face = analyzer_.analyse(neutral_photo);
  analyzer_.reset();
  if (!face) throw Error("neutral photo: no face found");
  selector_.calibrate(measure_features(face->landmarks, &neutral_photo));
  return face->landmarks;
}

std::optional<protocol::ExpressionCode> FaceCoder::code(const Image& frame, double now) {
  last_face_ = analyzer_.analyse(frame);
  const ExpressionState state =
      selector_.update(last_face_ ? std::optional(measure_features(last_face_->landmarks, &frame)) : std::nullopt);
  return stream_.next(state, now);
}

}  // namespace inkwire
