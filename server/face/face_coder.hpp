#pragma once
// The server's face pipeline for one speaker (SPEC F2-F4): frame -> landmarks -> features ->
// calibrated, steadied expression -> the few bytes to send. One object per camera.
#include <optional>

#include "protocol/messages.hpp"
#include "server/face/expression_selector.hpp"
#include "server/face/expression_stream.hpp"
#include "server/face/face_analyzer.hpp"

namespace inkwire {

class FaceCoder {
 public:
  explicit FaceCoder(FaceAnalyzerOptions analysis = {}, ExpressionSelector::Options selection = {}, double keepalive_seconds = 1.0)
      : analyzer_(std::move(analysis)), selector_(selection), stream_(keepalive_seconds) {}

  // Calibrates from a neutral photo of the speaker instead of the first frames; returns its
  // landmarks (what the receiver needs with the photo). Throws when the photo shows no face.
  FaceLandmarks calibrate(const Image& neutral_photo);

  // One camera frame at time `now` (seconds): the message to send, if any.
  std::optional<protocol::ExpressionCode> code(const Image& frame, double now);

  const std::optional<FaceAnalysis>& last_face() const { return last_face_; }
  const ExpressionStream& stream() const { return stream_; }

 private:
  FaceAnalyzer analyzer_;
  ExpressionSelector selector_;
  ExpressionStream stream_;
  std::optional<FaceAnalysis> last_face_;
};

}  // namespace inkwire
