#pragma once
// One publisher's face video (SPEC F17), read as hostile input: each VP8 frame is checked before
// libavcodec sees it (its frame tag, a key frame's picture size within kMaxVideoSide, the
// message's key flag, a stream that starts with a key frame and misses none of its sequence),
// then decoded into an RGBA picture. Anything wrong throws inkwire::Error with the reason and
// resets the stream: nothing is decoded again until its next key frame, which the server asks
// the publisher for.
#include <cstdint>
#include <memory>
#include <optional>

#include "common/image.hpp"
#include "protocol/messages.hpp"

namespace inkwire::server {

// What a VP8 frame's first bytes say (RFC 6386 9.1), read without decoding anything.
struct Vp8FrameHeader {
  bool key = false;
  int width = 0, height = 0;  // key frames only
};
// Throws inkwire::Error when the bytes are no VP8 frame this server reads: too short, a
// reserved version, a first partition past the end, a hidden frame, a key frame without its
// start code or whose picture is scaled, smaller than 16 or larger than kMaxVideoSide.
Vp8FrameHeader read_vp8_header(const protocol::Bytes& frame);

class FaceVideoDecoder {
 public:
  FaceVideoDecoder();
  ~FaceVideoDecoder();
  FaceVideoDecoder(const FaceVideoDecoder&) = delete;
  FaceVideoDecoder& operator=(const FaceVideoDecoder&) = delete;

  // The picture `frame` shows; throws inkwire::Error (and waits for a key frame) when it cannot.
  Image decode(const protocol::FaceVideo& frame);
  // True until a key frame starts the stream, and again after any frame that failed.
  bool waiting_for_key() const { return !sequence_; }

 private:
  struct Codec;
  void reset();

  std::unique_ptr<Codec> codec_;
  std::optional<uint32_t> sequence_;  // of the last frame decoded
  int width_ = 0, height_ = 0;        // the stream's picture, from its key frame
};

}  // namespace inkwire::server
