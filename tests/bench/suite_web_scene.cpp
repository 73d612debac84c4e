// --suite web-scene (SPEC W5-W7): the browser's renderer against the native one, per style.
// tests/web/web_scene_bench.py measures the element in Debian's headless chromium, on SwiftShader
// and on llvmpipe (frames per second during a drag at 620x500, first-frame bytes and time, the
// module's compressed size, PSNR against the native client); this suite times the same renderers
// natively on the same mesh, size and turning camera in the same run and gives the ratio. The
// first rows, "bare-mesh" and "bare-quads", are the platform's own ratios: the least GL a frame of
// the default style's and of the painterly style's kind of work can be, written by hand in script
// and timed natively (bare_frame.hpp). No rows, and a message, without the browser or the script.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "bare_frame.hpp"
#include "bench_harness.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/styles.hpp"
#include "common/camera.hpp"

namespace inkwire::bench {

std::vector<Result> run_web_scene_suite(Harness& harness) {
  namespace fs = std::filesystem;
  std::vector<std::string> names;
  for (const StyleInfo& s : styles()) names.push_back(s.name);
  names.push_back("hatching+sketch-pencil");

  const fs::path script = fs::path(INKWIRE_SOURCE_DIR) / "tests/web/web_scene_bench.py";
  const fs::path out = fs::temp_directory_path() / "inkwire-bench-web-scene";
  fs::create_directories(out);

  // The native client's renderers on the same mesh, size and camera, turning as the drag does.
  BenchObject cow{.name = "cow", .object = load_scene_object(fs::path(INKWIRE_MESH_DIR) / "cow.off", 0, kSceneDiagonal), .frame = {}};
  cow.frame.camera = scene_orbit_camera(30, 20, 1.4f);
  cow.frame.light_direction = default_light_direction(cow.frame.camera);
  cow.frame.viewport = {kWidth, kHeight};
  std::map<std::string, Result> native;
  std::vector<Result> rows;
  // The platform's references, drawn over white: each picture's covered share says both drew it.
  const fs::path bare_json = out / "bare-frames.json";
  nlohmann::json bare_pages = nlohmann::json::array();
  const Backdrop white(BackdropSpec::parse("#ffffff"));
  for (const BareFrame::Kind kind : {BareFrame::Kind::Mesh, BareFrame::Kind::Quads}) {
    BareFrame bare(kind);
    bare_pages.push_back(bare.page_json());
    Result& r = native[bare.name()] = harness.time_frames(bare, cow, harness.options().frames, nullptr, &white);
    const Image picture = harness.canvas().read();
    size_t covered = 0;
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x) covered += picture.at(x, y)[0] != 255;
    r.counters["native_covered_share"] = double(covered) / (double(picture.width) * picture.height);
  }
  std::ofstream(bare_json) << bare_pages.dump();
  // The browser's WebGL2 on either software rasteriser (tests/web/browser_support.py): SwiftShader,
  // what a browser without a GPU uses, and ANGLE over llvmpipe, the one the native client uses.
  for (const std::string gl : {"swiftshader", "llvmpipe"}) {
    const fs::path json = out / ("web-scene-" + gl + ".json");
    fs::remove(json);
    std::string command = "INKWIRE_BROWSER_GL=" + gl + " /usr/bin/python3 '" + script.string() + "' '" + INKWIRE_BIN_DIR + "' '" +
                          (out / gl).string() + "' '" + json.string() + "' '" + bare_json.string() + "'";
    for (const std::string& n : names) command += " '" + n + "'";
    if (std::system(command.c_str()) != 0 || !fs::exists(json)) {
      std::fprintf(stderr, "inkwire-bench: the web-scene suite did not run (%s): no web-scene rows for %s\n", command.c_str(), gl.c_str());
      continue;
    }
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
    harness.set_machine("browser_gl_renderer_" + gl, j.value("browser_gl_renderer", ""));
    for (const auto& row : j.at("rows")) {
      const std::string style = row.at("style");
      if (!native.count(style)) {
        // As the native client draws the style: over its own backdrop (paper, canvas, a colour),
        // which the element draws too.
        auto renderer = make_renderer(style);
        renderer->prepare(cow.object);
        const Backdrop backdrop(BackdropSpec::parse(default_backdrop(style)));
        native[style] = harness.time_frames(*renderer, cow, harness.options().frames, nullptr, &backdrop);
      }
      Result r = native[style];
      r.suite = "web-scene", r.renderer = style, r.variant = "style=" + style + ",gl=" + gl;
      r.counters["native_fps"] = r.fps_median;
      r.counters["fps"] = row.at("fps").get<double>();
      r.counters["rel_native"] = r.counters["fps"] / r.fps_median;
      if (row.contains("covered_share")) r.counters["covered_share"] = row.at("covered_share").get<double>();
      if (row.contains("psnr_vs_native")) r.counters["psnr_vs_native"] = row.at("psnr_vs_native").get<double>();
      r.counters["ms_frame"] = 1000.0 / r.counters["fps"];
      r.counters["ms_in_page_calls"] = row.at("ms_in_page_calls").get<double>();
      r.counters["ms_first_frame"] = j.at("ms_first_frame").get<double>();
      r.counters["bytes_first_frame"] = j.at("bytes_first_frame").get<double>();
      r.counters["module_bytes_compressed"] = j.at("module_bytes_compressed").get<double>();
      r.fps_median = r.fps_min = r.fps_max = r.counters["fps"];  // the browser's; the native figures are counters
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

}  // namespace inkwire::bench
