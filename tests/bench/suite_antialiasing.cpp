// Suite "antialiasing": what 4x multisampling (the default for stills, videos and the window)
// costs each kind of renderer: default, comic-extended, a sketcher and hatching, with and
// without it, on the LOD series' middle and largest objects, in one run. `rel_no_aa` is fps
// with antialiasing over fps without it, same renderer, same object; `rel_default` is over the
// default renderer without it.
#include <algorithm>
#include <map>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"

namespace inkwire::bench {

std::vector<Result> run_antialiasing_suite(Harness& harness) {
  constexpr int kSamples = 4;
  const int frames = std::min(harness.options().frames, 300);
  Canvas multisampled(kWidth, kHeight, kSamples);
  std::vector<Result> results;
  for (BenchObject& object : harness.lod_series()) {
    if (object.name != "lod3" && object.name != "lod5") continue;
    double default_fps = 0.0;
    for (const std::string style : {"default", "comic-extended", "sketch-pencil", "hatching"}) {
      auto renderer = make_renderer(style);
      renderer->prepare(object.object);
      Result off = harness.time_frames(*renderer, object, frames);
      Result on = harness.time_frames(*renderer, object, frames, &multisampled);
      if (style == "default") default_fps = off.fps_median;
      for (auto [r, samples] : {std::pair{&off, 1}, std::pair{&on, kSamples}}) {
        r->suite = "antialiasing";
        r->renderer = style;
        r->variant = "msaa=" + std::to_string(samples);
        r->rel_default = r->fps_median / default_fps;
        r->counters["rel_no_aa"] = r->fps_median / off.fps_median;
        r->counters["samples"] = samples;
      }
      results.push_back(off);
      results.push_back(on);
    }
  }
  return results;
}

}  // namespace inkwire::bench
