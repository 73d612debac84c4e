#include "server/face/face_coder.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace inkwire {

FaceLandmarks FaceCoder::calibrate(const Image& neutral_photo) {
  analyzer_.reset();
  const auto face = analyzer_.analyse(neutral_photo);
  analyzer_.reset();
  if (!face) throw Error("neutral photo: no face found");
  reader_.calibrate(face->landmarks, &neutral_photo);
  return face->landmarks;
}

FaceCoder::Sent FaceCoder::read(const Image& frame, double now) {
  last_face_ = analyzer_.analyse(frame);
  const FaceState& state = reader_.read(last_face_ ? std::optional(last_face_->landmarks) : std::nullopt, &frame);
  return {.code = stream_.next(reader_.expression(), now),
          .layers = layers_.next(state, now, 0, uint32_t(std::max(0.0, now) * 1000.0))};
}

}  // namespace inkwire
