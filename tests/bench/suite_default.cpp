// Suite "default": the default renderer over the LOD series at the study's pose (SPEC G4, G5).
#include <glm/gtc/matrix_inverse.hpp>

#include "bench_harness.hpp"
#include "client/render/coverage.hpp"
#include "client/render/styles.hpp"
#include "common/orientation.hpp"

namespace inkwire::bench {

std::vector<Result> run_default_suite(Harness& harness) {
  std::vector<Result> results;
  for (BenchObject& object : harness.lod_series()) {
    auto renderer = make_renderer("default");
    renderer->prepare(object.object);
    Result r = harness.time_frames(*renderer, object, harness.options().frames);
    r.suite = "default";
    r.renderer = "default";
    r.rel_default = 1.0;
    // Front faces: what back-face culling keeps, by the exact per-triangle test (SPEC G3).
    const glm::vec3 eye = glm::vec3(glm::inverse(object.frame.model) * glm::vec4(object.frame.camera.position, 1.0f));
    std::vector<uint8_t> front;
    r.counters["front_faces"] = double(classify_faces(object.object.mesh, object.object.topology, eye, front));
    r.counters["coverage"] = measure_coverage(*renderer, object.frame, harness.canvas());
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace inkwire::bench
