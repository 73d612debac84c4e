// libFuzzer target: tween data from outside (the tween-data message, files). Whatever decodes
// must encode again and decode to the same value.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "common/tween/tween_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const inkwire::TweenData d = inkwire::decode_tween({data, size});
    if (inkwire::decode_tween(inkwire::encode_tween(d)) != d) __builtin_trap();
  } catch (const inkwire::Error&) {
  }
  return 0;
}
