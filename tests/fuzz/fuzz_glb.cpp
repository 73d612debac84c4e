// libFuzzer target: the GLB model a scene session sends, as the browser's module reads it. What
// reads must be a mesh every renderer can draw (validate_mesh passes again).
#include <cstddef>
#include <cstdint>
#include <span>

#include "common/error.hpp"
#include "common/glb_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const inkwire::Mesh mesh = inkwire::read_glb_mesh(std::span<const uint8_t>(data, size), "fuzz.glb");
    inkwire::validate_mesh(mesh);
  } catch (const inkwire::Error&) {
  }
  return 0;
}
