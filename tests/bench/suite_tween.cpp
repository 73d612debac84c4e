// Suites "tween" and "landmarks" (SPEC T10, T7) at 256x256 on a textured product rendered into a
// ring (and a sphere) of samples: fps of each synthesis method beside the default renderer
// drawing the mesh itself, tween bytes per pair, and automatic landmarks against the exact
// correspondences the mesh gives (seconds, wrong fraction, mean error).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include <glm/geometric.hpp>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/error.hpp"
#include "common/tween/view_sphere.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire::bench {
namespace {

constexpr int kSize = 256;
constexpr float kDistance = 1.4f;  // bounding-box diagonals, as the tween style samples
const std::filesystem::path kProduct = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";

// The packaged textured truck, else the largest object of the LOD series.
BenchObject product(Harness& harness) {
  BenchObject b;
  if (std::filesystem::exists(kProduct)) {
    b.name = "truck";
    b.object = load_scene_object(kProduct);
  } else {
    std::fprintf(stderr, "inkwire-bench: %s is missing (assimp-testmodels): using the LOD series\n", kProduct.c_str());
    b.name = harness.lod_series().back().name;
    b.object = harness.lod_series().back().object;
  }
  b.frame.viewport = {kSize, kSize};
  b.frame.camera = orbit_camera(b.object.topology.bounds, 7.5f, 0.0f, kDistance);
  b.frame.light_direction = default_light_direction(b.frame.camera);
  return b;
}

}  // namespace

std::vector<Result> run_tween_suite(Harness& harness) {
  const int frames = harness.options().frames;
  BenchObject object = product(harness);
  Canvas canvas(kSize, kSize, 1);
  std::vector<Result> results;
  double default_fps = 0.0;
  struct Variant {
    const char* name;
    std::vector<std::string> settings;
  };
  const std::vector<Variant> variants = {
      {"", {}},
      {"nearest", {"method=nearest"}},
      {"crossfade", {"method=crossfade"}},
      {"linear", {"method=linear"}},
      {"bilinear-layered", {"method=bilinear", "overlap=layered"}},
      {"bilinear-depthclear", {"method=bilinear", "overlap=depth-clear"}},
      {"trilinear", {"method=trilinear"}},
  };
  for (const Variant& v : variants) {
    const bool reference = *v.name == '\0';
    auto renderer = reference ? make_renderer("default") : make_renderer("tween", v.settings);
    renderer->prepare(object.object);
    Result r = harness.time_frames(*renderer, object, frames, &canvas);
    r.suite = "tween";
    r.renderer = reference ? "default" : "tween";
    r.variant = v.name;
    if (reference) default_fps = r.fps_median;
    r.rel_default = r.fps_median / default_fps;
    for (const auto& [key, value] : renderer->counters()) r.counters[key] = value;
    if (!reference) {
      r.counters["bytes_per_pair"] = r.counters["bytes_per_cell"];
      r.counters.erase("bytes_per_cell");
      r.counters.erase("cell");
    }
    results.push_back(std::move(r));
    std::fprintf(stderr, "inkwire-bench: tween %s done\n", reference ? "default" : v.name);
  }
  return results;
}

std::vector<Result> run_landmarks_suite(Harness& harness) {
  BenchObject object = product(harness);
  const int samples = 24;
  const MeshSamples set = render_mesh_samples(object.object, ring_directions(samples), kSize, kDistance);
  LandmarkOptions options;  // 65 landmarks, the study's count
  std::vector<double> seconds;
  double error_sum = 0.0;
  int found = 0, checked = 0, wrong = 0, unverifiable = 0;
  std::map<std::string, double> rejected;  // per pair, by rule
  constexpr float kWrongPixels = 3.0f;
  for (int i = 0; i < samples; ++i) {
    const int j = (i + 1) % samples;
    const cv::Mat a = grey_of(set.images[size_t(i)]), b = grey_of(set.images[size_t(j)]);
    const auto start = std::chrono::steady_clock::now();
    LandmarkStats stats;
    const std::vector<Landmark> landmarks = find_landmarks(a, b, options, &stats);
    for (const auto& [name, count] : std::initializer_list<std::pair<const char*, int>>{
             {"candidates", stats.candidates}, {"rejected_border", stats.near_border}, {"rejected_spacing", stats.too_close},
             {"rejected_weak", stats.weak}, {"rejected_self_similar", stats.not_distinctive}, {"rejected_no_match", stats.no_match},
             {"rejected_not_unique", stats.not_unique}, {"rejected_not_found_back", stats.not_found_back},
             {"rejected_inconsistent", stats.inconsistent}})
      rejected[name] += double(count) / samples;
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    for (const Landmark& l : landmarks) {
      ++found;
      // The truth: the surface under the landmark, projected into the other sample. A landmark
      // on the background side of the outline has no surface point: it cannot be checked.
      if (!set.surface_point(i, l.source)) {
        ++unverifiable;
        continue;
      }
      ++checked;
      const auto truth = set.true_position(i, l.source, j);
      const float error = truth ? glm::length(*truth - l.target) : 1e9f;
      if (error > kWrongPixels) {
        ++wrong;
      } else {
        error_sum += error;
      }
    }
  }
  std::sort(seconds.begin(), seconds.end());
  Result r;
  r.suite = "landmarks";
  r.renderer = "landmarks";
  r.variant = "ring24,256x256";
  r.object = object.name;
  r.faces = object.object.mesh.face_count();
  r.frames = samples;
  r.counters["landmarks"] = double(found) / samples;
  r.counters["seconds"] = seconds[seconds.size() / 2];
  r.counters["wrong_fraction"] = checked ? double(wrong) / checked : 0.0;
  r.counters["mean_error_px"] = checked > wrong ? error_sum / double(checked - wrong) : 0.0;
  r.counters["unverifiable_fraction"] = found ? double(unverifiable) / found : 0.0;
  r.counters.insert(rejected.begin(), rejected.end());
  return {r};
}

}  // namespace inkwire::bench
