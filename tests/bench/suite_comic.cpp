// Suite "comic": the study's tables 8, 9, 11 and 12 (SPEC C10) over the LOD series. Every row
// has the default renderer's fps on the same object from the same run as its reference.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "bench_harness.hpp"
#include "client/render/styles.hpp"

namespace inkwire::bench {
namespace {

// The same object with a texture: UVs by spherical projection about the bounding-box centre
// and a generated checker, so the textured path (base texture x shade map in one pass, C9)
// can be timed on every LOD.
BenchObject textured_copy(const BenchObject& source) {
  Mesh mesh = source.object.mesh;
  const glm::vec3 centre = source.object.topology.bounds.centre();
  mesh.corner_uvs.resize(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const glm::vec3 d = glm::normalize(mesh.positions[mesh.triangles[t][c]] - centre);
      mesh.corner_uvs[t][c] = {0.5f + std::atan2(d.z, d.x) / (2.0f * std::numbers::pi_v<float>),
                               0.5f + std::asin(std::clamp(d.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>};
    }
  BenchObject out{source.name, make_scene_object(std::move(mesh)), source.frame};
  Image checker(256, 256);
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const uint8_t v = ((x / 32) + (y / 32)) % 2 ? 230 : 150;
      uint8_t* p = checker.at(x, y);
      p[0] = v, p[1] = uint8_t(v * 0.8f), p[2] = uint8_t(v * 0.6f), p[3] = 255;
    }
  out.object.material_images[0] = checker;
  return out;
}

struct Variant {
  std::string renderer, variant;
  std::vector<std::string> settings;
  bool textured = false;
};

}  // namespace

std::vector<Result> run_comic_suite(Harness& harness) {
  const std::vector<Variant> variants = {
      {"comic", "", {}},
      {"comic", "backfaces-outline", {"outline=backfaces"}},  // the study's outline method
      {"comic-extended", "triangle", {"orientation=triangle"}},
      {"comic-extended", "triangle-corrected", {"orientation=triangle-corrected"}},
      {"comic-extended", "triangle-exact", {"orientation=triangle-exact"}},
      {"comic-extended", "k=1", {"orientation=vertex", "k=1"}},
      {"comic-extended", "k=2", {"orientation=vertex", "k=2"}},
      {"comic-extended", "k=3", {"orientation=vertex", "k=3"}},
      {"comic-extended", "coloured-silhouette", {"orientation=vertex", "k=1", "coloured_outline=true"}},
      {"comic-extended", "textured", {"orientation=vertex", "k=1"}, true},
  };
  const int frames = harness.options().frames;
  std::vector<Result> results;
  for (BenchObject& plain : harness.lod_series()) {
    const BenchObject textured = textured_copy(plain);
    double default_fps[2] = {0, 0};  // plain, textured
    for (int t = 0; t < 2; ++t) {
      const BenchObject& object = t ? textured : plain;
      auto reference = make_renderer("default");
      reference->prepare(object.object);
      Result r = harness.time_frames(*reference, object, frames);
      r.suite = "comic";
      r.renderer = "default";
      r.variant = t ? "textured" : "";
      r.rel_default = 1.0;
      default_fps[t] = r.fps_median;
      results.push_back(std::move(r));
    }
    for (const Variant& v : variants) {
      const BenchObject& object = v.textured ? textured : plain;
      auto renderer = make_renderer(v.renderer, v.settings);
      renderer->prepare(object.object);
      Result r = harness.time_frames(*renderer, object, frames);
      r.suite = "comic";
      r.renderer = v.renderer;
      r.variant = v.variant;
      r.rel_default = r.fps_median / default_fps[v.textured ? 1 : 0];
      r.counters["front_faces"] = renderer->counters().at("front_faces");
      results.push_back(std::move(r));
    }
    std::fprintf(stderr, "inkwire-bench: comic %s done\n", plain.name.c_str());
  }
  return results;
}

}  // namespace inkwire::bench
