// libFuzzer target: an HTTP request head as anyone may send it to the HTTP listener (at most
// 8 KiB, as the listener reads it). Must end in a Request or inkwire::Error, nothing else.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.hpp"
#include "server/web/http_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 8192) return 0;
  try {
    const inkwire::server::Request r = inkwire::server::parse_head(std::string(reinterpret_cast<const char*>(data), size));
    // What parsed has a method, a path and lower-case header names.
    if (r.method.empty() || r.path.empty()) __builtin_trap();
    for (const auto& [name, value] : r.headers)
      if (name != inkwire::server::lower(name)) __builtin_trap();
  } catch (const inkwire::Error&) {
  }
  return 0;
}
