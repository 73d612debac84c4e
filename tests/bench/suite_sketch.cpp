// Suite "sketch": the study's figures 55 and 56 (SPEC S8) over the LOD series: fps against
// total and drawn edges for every sketcher and the hidden-line drawing, with the default
// renderer on the same objects.
#include <cstdio>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"

namespace inkwire::bench {

std::vector<Result> run_sketch_suite(Harness& harness) {
  const std::vector<std::string> sketchers = {"hidden-line", "sketch-recursive", "sketch-segments", "sketch-pencil", "sketch-charcoal", "sketch-chalk"};
  const int frames = harness.options().frames;
  std::vector<Result> results;
  for (BenchObject& object : harness.lod_series()) {
    auto reference = make_renderer("default");
    reference->prepare(object.object);
    Result base = harness.time_frames(*reference, object, frames);
    base.suite = "sketch";
    base.renderer = "default";
    base.rel_default = 1.0;
    const double default_fps = base.fps_median;
    results.push_back(std::move(base));
    for (const std::string& name : sketchers) {
      auto renderer = make_renderer(name);
      renderer->prepare(object.object);
      Result r = harness.time_frames(*renderer, object, frames);
      r.suite = "sketch";
      r.renderer = name;
      r.rel_default = r.fps_median / default_fps;
      for (const auto& [key, value] : renderer->counters()) r.counters[key] = value;
      results.push_back(std::move(r));
    }
    std::fprintf(stderr, "inkwire-bench: sketch %s done\n", object.name.c_str());
  }
  return results;
}

}  // namespace inkwire::bench
