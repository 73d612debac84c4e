// Suite "hatching": the study's figure 54 (SPEC S8): hatching fps per variant over the LOD
// series, with the default renderer on the same objects.
#include <cstdio>

#include <glm/gtc/matrix_inverse.hpp>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"
#include "common/orientation.hpp"

namespace inkwire::bench {

std::vector<Result> run_hatching_suite(Harness& harness) {
  const int frames = harness.options().frames;
  std::vector<Result> results;
  for (BenchObject& object : harness.lod_series()) {
    const glm::vec3 eye = glm::vec3(glm::inverse(object.frame.model) * glm::vec4(object.frame.camera.position, 1.0f));
    std::vector<uint8_t> front;
    const double front_faces = double(classify_faces(object.object.mesh, object.object.topology, eye, front));
    double default_fps = 0.0;
    // Rows: the default renderer; each variant (as a user picks it: with its pencil outline); the
    // tones alone, without the outline; the threshold image turned off the pixel grid, where it
    // is filtered (unturned, a texel is a pixel and the nearest texel is exact).
    const std::vector<std::pair<std::string, std::vector<std::string>>> rows = {
        {"", {}},
        {"threshold", {"variant=threshold"}},
        {"threshold,outline=none", {"variant=threshold", "outline=none"}},
        {"threshold,angle=30", {"variant=threshold", "angle=30"}},
        {"3d-texture", {"variant=3d-texture"}},
        {"multipass", {"variant=multipass"}}};
    for (const auto& [variant, settings] : rows) {
      const bool reference = variant.empty();
      auto renderer = reference ? make_renderer("default") : make_renderer("hatching", settings);
      renderer->prepare(object.object);
      Result r = harness.time_frames(*renderer, object, frames);
      r.suite = "hatching";
      r.renderer = reference ? "default" : "hatching";
      r.variant = variant;
      if (reference) default_fps = r.fps_median;
      r.rel_default = r.fps_median / default_fps;
      r.counters["front_faces"] = front_faces;
      for (const auto& [key, value] : renderer->counters()) r.counters[key] = value;
      results.push_back(std::move(r));
    }
    std::fprintf(stderr, "inkwire-bench: hatching %s done\n", object.name.c_str());
  }
  return results;
}

}  // namespace inkwire::bench
