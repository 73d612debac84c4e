// libFuzzer target: one voice packet as a call member sends it (server/call/voice_analysis.hpp):
// refused with a reason or read, never a crash; a reading's level and mouth are in range.
#include <cstddef>
#include <cstdint>
#include <span>

#include "server/call/voice_analysis.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static inkwire::server::VoiceAnalysis voice;  // one decoder, as a member's: state carries over
  std::string reason;
  const auto reading = voice.read(std::span<const uint8_t>(data, size), &reason);
  if (reading && (reading->samples <= 0 || reading->samples > 960 || !(reading->level_db <= 1.0f))) __builtin_trap();
  if (!reading && reason.empty()) __builtin_trap();
  return 0;
}
