// --suite window: what the windowed client costs a core while it sits idle on a still style,
// measured by tests/window/client_window_test.py (a real GLFW window on llvmpipe under a virtual
// display, xvfb-run) with --bench; the test itself checks only that an idle window draws nothing.
// No rows, and a message, without a display, xdotool or ffmpeg.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "bench_harness.hpp"

namespace inkwire::bench {

std::vector<Result> run_window_suite(Harness& harness) {
  namespace fs = std::filesystem;
  const fs::path script = fs::path(INKWIRE_SOURCE_DIR) / "tests/window/client_window_test.py";
  const fs::path out = fs::path(harness.options().output_dir.empty() ? fs::temp_directory_path().string() : harness.options().output_dir) /
                       "window-bench";
  const fs::path json = out.string() + ".json";
  fs::remove(json);
  // The script's own display when the bench has none.
  const std::string display = std::getenv("DISPLAY") ? "" : "xvfb-run -a -s '-screen 0 1024x768x24' ";
  const std::string command = display + "/usr/bin/python3 '" + script.string() + "' '" + INKWIRE_BIN_DIR + "' '" + out.string() + "' --bench '" +
                              json.string() + "'";
  if (std::system(command.c_str()) != 0) std::fprintf(stderr, "inkwire-bench: the window script failed a check (%s)\n", command.c_str());
  if (!fs::exists(json)) {
    std::fprintf(stderr, "inkwire-bench: no window rows (%s wrote none: no display, xdotool or ffmpeg?)\n", script.c_str());
    return {};
  }
  std::vector<Result> rows;
  // Parsed into a name of its own: a range-for over a member of a temporary would dangle.
  const nlohmann::json measured = nlohmann::json::parse(std::ifstream(json));
  for (const auto& row : measured.at("rows")) {
    Result r{.suite = "window", .renderer = "window", .variant = row.at("variant"), .object = "cow"};
    for (const auto& [key, value] : row.at("counters").items()) r.counters[key] = value.get<double>();
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace inkwire::bench
