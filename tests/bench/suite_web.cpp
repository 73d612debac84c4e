// --suite web (SPEC W2): the browser's figures, measured by tests/web/web_bench.py in Debian's
// headless chromium on loopback (the element against a 72-photo spin page; see that script),
// turned into the bench's rows. No rows, and a message, without the browser or the script.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "bench_harness.hpp"

namespace inkwire::bench {

std::vector<Result> run_web_suite(Harness& harness) {
  namespace fs = std::filesystem;
  const fs::path script = fs::path(INKWIRE_SOURCE_DIR) / "tests/web/web_bench.py";
  const fs::path out = fs::temp_directory_path() / "inkwire-bench-web", json = out / "web.json";
  fs::create_directories(out);
  fs::remove(json);
  const std::string command = "/usr/bin/python3 '" + script.string() + "' '" + INKWIRE_BIN_DIR + "' '" + out.string() + "' '" + json.string() + "'";
  if (std::system(command.c_str()) != 0 || !fs::exists(json)) {
    std::fprintf(stderr, "inkwire-bench: the web suite did not run (%s): no web rows\n", command.c_str());
    return {};
  }
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  harness.set_machine("browser_gl_renderer", j.value("browser_gl_renderer", ""));
  std::vector<Result> rows;
  for (const auto& row : j.at("rows")) {
    Result r;
    r.suite = "web", r.renderer = "web", r.variant = row.at("variant"), r.object = "truck";
    for (const auto& [key, value] : row.at("counters").items()) r.counters[key] = value.get<double>();
    if (r.counters.count("fps")) r.fps_median = r.counters["fps"];  // the module row times loading, not frames
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace inkwire::bench
