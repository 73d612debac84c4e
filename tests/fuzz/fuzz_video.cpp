// libFuzzer target: a call member's face video as the server reads it (SPEC F17,
// server/call/face_video_decoder.hpp), through libavcodec's VP8 decoder as it is. The input is
// a stream of frames, each a 2-byte little-endian length and its bytes, numbered one after
// another and flagged key as their own tag says: every frame is refused with a reason or
// decoded into a picture within the limits, never a crash.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "server/call/face_video_decoder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  inkwire::server::FaceVideoDecoder decoder;  // one stream per input
  uint32_t sequence = 0;
  for (size_t at = 0; at + 2 <= size;) {
    const size_t n = std::min(size_t(data[at] | data[at + 1] << 8), size - at - 2);
    at += 2;
    inkwire::protocol::FaceVideo frame{.time_ms = sequence * 66, .sequence = ++sequence, .frame_width = 640, .frame_height = 480,
                                        .x = 0, .y = 0, .width = 320, .height = 320, .key = n > 0 && (data[at] & 1) == 0,
                                        .vp8 = inkwire::protocol::Bytes(data + at, data + at + n)};
    at += n;
    try {
      const inkwire::Image picture = decoder.decode(frame);
      if (picture.width < 16 || picture.height < 16 || picture.width > inkwire::protocol::kMaxVideoSide ||
          picture.height > inkwire::protocol::kMaxVideoSide || picture.pixels.size() != size_t(picture.width) * picture.height * 4)
        __builtin_trap();
    } catch (const inkwire::Error& e) {
      if (!*e.what() || !decoder.waiting_for_key()) __builtin_trap();
    }
  }
  return 0;
}
