// libFuzzer target: tween data from outside (tween assets, and the single cell a tween-data
// message carries). Whatever decodes must encode again and decode to the same value. The
// first two bytes choose the product a cell is read against (image side, sample count).
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
  if (size >= 2) {
    const int side = 16 + data[0] * 16, samples = 2 + data[1];
    try {
      const inkwire::TweenCell c = inkwire::decode_tween_cell({data + 2, size - 2}, side, side, samples);
      if (inkwire::decode_tween_cell(inkwire::encode_tween_cell(c, side, side, samples), side, side, samples) != c) __builtin_trap();
    } catch (const inkwire::Error&) {
    }
  }
  return 0;
}
