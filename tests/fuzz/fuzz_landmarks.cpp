// libFuzzer target: the landmarks asset that comes with a speaker's neutral photo. Whatever
// parses must write out and parse again to the same points.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "common/face/landmarks_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const inkwire::FaceLandmarks l = inkwire::parse_landmarks(std::string(reinterpret_cast<const char*>(data), size));
    if (inkwire::parse_landmarks(inkwire::landmarks_to_json(l)) != l) __builtin_trap();
  } catch (const inkwire::Error&) {
  }
  return 0;
}
