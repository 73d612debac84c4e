// libFuzzer target: arbitrary bytes as a stream arriving from a peer (framing + every decoder).
#include <cstddef>
#include <cstdint>

#include "protocol/framing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace inkwire::protocol;
  FrameDecoder decoder;
  try {
    // Two pieces, so frames split across reads are exercised too.
    const size_t half = size / 2;
    decoder.feed(data, half);
    while (decoder.next()) {
    }
    decoder.feed(data + half, size - half);
    while (auto m = decoder.next()) {
      // A decoded message must encode again (every field within its limits).
      encode(*m);
    }
  } catch (const ProtocolError&) {
  }
  return 0;
}
