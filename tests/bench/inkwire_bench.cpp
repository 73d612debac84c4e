// inkwire-bench: prints the performance tables and writes them as JSON (docs/cli.md says the shape).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "bench_harness.hpp"
#include "common/error.hpp"

using namespace inkwire;
using namespace inkwire::bench;

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

void print_table(const std::vector<Result>& results) {
  std::printf("%-10s %-16s %-22s %-6s %7s %6s %10s %9s %9s %8s  %s\n", "suite", "renderer", "variant", "object", "faces",
              "frames", "fps_median", "fps_min", "fps_max", "rel_def", "counters");
  for (const Result& r : results) {
    std::string counters;
    for (const auto& [k, v] : r.counters) {
      char buf[64];
      std::snprintf(buf, sizeof(buf), "%s=%.4g ", k.c_str(), v);
      counters += buf;
    }
    std::printf("%-10s %-16s %-22s %-6s %7zu %6d %10.1f %9.1f %9.1f %8.3f  %s\n", r.suite.c_str(), r.renderer.c_str(),
                r.variant.c_str(), r.object.c_str(), r.faces, r.frames, r.fps_median, r.fps_min, r.fps_max, r.rel_default,
                counters.c_str());
  }
}

nlohmann::json to_json(const Result& r) {
  return {{"suite", r.suite},           {"renderer", r.renderer},       {"variant", r.variant},
          {"object", r.object},         {"faces", r.faces},             {"frames", r.frames},
          {"fps_median", r.fps_median}, {"fps_min", r.fps_min},         {"fps_max", r.fps_max},
          {"rel_default", r.rel_default}, {"counters", r.counters}};
}

}  // namespace

int main(int argc, char** argv) {
  std::string suite = "all", json_path;
  Options options;
  options.mesh = std::string(INKWIRE_MESH_DIR) + "/bull.off";
  CLI::App app{"inkwire-bench: speed and quality figures of every renderer, the network and the product turntable, as a table and as JSON"};
  app.add_option("--suite", suite, "default|comic|sketch|hatching|antialiasing|painterly|tween|turntable|web|web-scene|landmarks|face|net|call|abuse|crash|soak|window|rooms|all");
  app.add_option("--frames", options.frames, "frames timed per measurement")->check(CLI::Range(1, 1000000));
  app.add_option("--minutes", options.minutes, "soak: minutes of churn (then 40 s for the crowd to leave and the deadlines to pass)")
      ->check(CLI::Range(0.1, 1440.0));
  app.add_option("--mesh", options.mesh, "source mesh of the LOD series (default: bull.off from libcgal-demo)");
  app.add_option("--gl", options.gl, "off-screen GL backend: osmesa, egl (surfaceless) or auto");
  app.add_option("--photos", options.photos, "turntable: a folder of real turntable photos to measure instead of the truck (repeatable)")
      ->check(CLI::ExistingDirectory);
  app.add_flag("--even-turn", options.even_turn,
               "turntable --photos: take the photos as evenly spaced instead of finding the turn from the matches, as add-product does");
  app.add_option("--json", json_path, "write results here")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    std::vector<std::pair<std::string, Suite>> chosen;
    std::string known;
    for (const auto& s : suites()) {
      known += (known.empty() ? "" : ", ") + s.first;
      if (suite == "all" || suite == s.first) chosen.push_back(s);
    }
    if (chosen.empty()) throw Error("suite '" + suite + "' is not available in this build (available: " + known + ", all)");

    options.output_dir = std::filesystem::path(json_path).parent_path().string();
    Harness harness(options);
    std::vector<Result> results;
    for (const auto& [name, run] : chosen) {
      std::fprintf(stderr, "inkwire-bench: running suite %s ...\n", name.c_str());
      auto rows = run(harness);
      results.insert(results.end(), rows.begin(), rows.end());
    }
    print_table(results);

    nlohmann::json out;
    // A suite may have made contexts of its own (a server rendering a product's samples): the
    // harness's is made current again before it is asked what it runs on.
    harness.context().make_current();
    out["machine"] = {{"cpu", cpu_model()},
                      {"gl_renderer", harness.context().gl_renderer()},
                      {"gl_backend", harness.context().backend()},
                      {"threads", std::thread::hardware_concurrency()}};
    for (const auto& [key, value] : harness.machine_notes()) out["machine"][key] = value;
    out["results"] = nlohmann::json::array();
    for (const Result& r : results) out["results"].push_back(to_json(r));
    std::ofstream(json_path) << out.dump(2) << "\n";
    if (!std::ofstream(json_path, std::ios::app)) throw Error("cannot write " + json_path);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "inkwire-bench: " << e.what() << "\n";
    return 1;
  }
}
