#pragma once
// The server's face pipeline for one speaker (SPEC F2-F4, F20-F22): frame -> landmarks -> the
// member's reading (server/face/face_reader.hpp: calibrated, steadied expression, layers, head
// pose) -> the few bytes to send, as the session-wide single code (expression-code) and as the
// layers a call's member-layers carries. One object per camera.
#include <optional>

#include "protocol/messages.hpp"
#include "server/face/expression_stream.hpp"
#include "server/face/face_analyzer.hpp"
#include "server/face/face_reader.hpp"
#include "server/face/layers_stream.hpp"

namespace inkwire {

class FaceCoder {
 public:
  explicit FaceCoder(FaceAnalyzerOptions analysis = {}, ExpressionSelector::Options selection = {}, double keepalive_seconds = 1.0)
      : analyzer_(std::move(analysis)), reader_(selection), stream_(keepalive_seconds), layers_(2.0 * keepalive_seconds) {}

  // Calibrates from a neutral photo of the speaker instead of the first frames; returns its
  // landmarks (what the receiver needs with the photo). Throws when the photo shows no face.
  FaceLandmarks calibrate(const Image& neutral_photo);

  // One camera frame at time `now` (seconds): what to send, if anything, each way.
  struct Sent {
    std::optional<protocol::ExpressionCode> code;
    std::optional<protocol::MemberLayers> layers;
  };
  Sent read(const Image& frame, double now);
  // The single code alone (a session's own speaker).
  std::optional<protocol::ExpressionCode> code(const Image& frame, double now) { return read(frame, now).code; }

  const std::optional<FaceAnalysis>& last_face() const { return last_face_; }
  const ExpressionStream& stream() const { return stream_; }
  const LayersStream& layers_stream() const { return layers_; }

 private:
  FaceAnalyzer analyzer_;
  FaceReader reader_;
  ExpressionStream stream_;
  LayersStream layers_;
  std::optional<FaceAnalysis> last_face_;
};

}  // namespace inkwire
