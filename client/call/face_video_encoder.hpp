#pragma once
// The face video a call member publishes (SPEC F17): pictures of one size encoded as VP8 by
// libvpx through libavcodec, set for a call's uplink: real time, no frame held back (so no
// hidden frames), a fixed bit rate, key frames only when asked for (the first one, a new size,
// the region jumping, the server asking).
#include <cstdint>
#include <memory>
#include <vector>

#include "common/image.hpp"

namespace inkwire {

class FaceVideoEncoder {
 public:
  // Throws inkwire::Error when this libavcodec has no libvpx encoder or it will not open.
  FaceVideoEncoder(int width, int height, double fps, int bitrate);
  ~FaceVideoEncoder();
  FaceVideoEncoder(const FaceVideoEncoder&) = delete;
  FaceVideoEncoder& operator=(const FaceVideoEncoder&) = delete;

  struct Frame {
    std::vector<uint8_t> vp8;
    bool key = false;
  };
  // `picture` must be width x height; `key` forces a key frame (the first one is always one).
  Frame encode(const Image& picture, uint32_t time_ms, bool key);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Codec;
  std::unique_ptr<Codec> codec_;
  int width_, height_;
};

}  // namespace inkwire
