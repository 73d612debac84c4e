#pragma once
// A call's limits, as the config sets them ("call_loudest"): apart from the call itself, so the
// config reads them without the call's machinery.
#include <cstddef>

namespace inkwire::server {

struct CallOptions {
  int loudest = 3;                // K: voices each member hears at once
  double crops_per_second = 15;   // per publisher
  double voice_per_second = 60;   // packets per publisher (20 ms packets are 50 a second)
  size_t max_crop_bytes = 32 * 1024;
  size_t max_voice_bytes = 400;
};

}  // namespace inkwire::server
