// libFuzzer target: a photo folder's calibration file (Middlebury *_par.txt, in a shop's or a
// lab's folder) read, then turned into the turntable's terms (the ring's frame, each camera's
// pose): must end in a camera or inkwire::Error with the reason, never a crash, whatever the
// numbers. The folder holds view0.png .. view3.png (empty: the reader only asks that they exist).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "common/error.hpp"
#include "server/products/calibrated_ring.hpp"
#include "server/tween/photo_ring.hpp"

namespace {

std::filesystem::path folder() {
  static const std::filesystem::path f = [] {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("inkwire-fuzz-calibration-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (int i = 0; i < 4; ++i) std::ofstream(dir / ("view" + std::to_string(i) + ".png"));
    return dir;
  }();
  return f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::filesystem::path file = folder() / "ring_par.txt";
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  try {
    const inkwire::PhotoRing ring = inkwire::load_photo_ring(folder(), file);
    const inkwire::RingFrame frame = inkwire::ring_frame(ring);
    inkwire::calibrated_camera(frame, ring.cameras, {480, 640}, {384, 512});
  } catch (const inkwire::Error&) {
  }
  return 0;
}
