// libFuzzer target: one message payload of a chosen type (the first byte picks the type), so
// the fuzzer reaches deep into each message's decoder without having to learn the framing.
#include <cstddef>
#include <cstdint>

#include "protocol/framing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace inkwire::protocol;
  if (size < 1) return 0;
  const auto type = MessageType(1 + data[0] % kMessageTypes);
  try {
    const Message m = decode(type, data + 1, size - 1);
    // What decodes must round-trip exactly.
    const Bytes again = encode(m);
    if (decode(type, again.data() + kHeaderBytes, again.size() - kHeaderBytes) != m) __builtin_trap();
  } catch (const ProtocolError&) {
  }
  return 0;
}
