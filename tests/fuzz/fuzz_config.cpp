// libFuzzer target: the server's JSON config (an operator's file, or one an attacker could
// plant): must end in a config or inkwire::Error with the reason, never a crash or a hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "server/config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    inkwire::server::ServerConfig::parse(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const inkwire::Error&) {
  }
  return 0;
}
