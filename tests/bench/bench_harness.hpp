#pragma once
// The benchmark harness every suite plugs into: the study's set-up (SPEC G4), frame timing,
// and result rows with the names docs/cli.md fixes.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/render/renderer.hpp"

namespace inkwire::bench {

struct Result {
  std::string suite, renderer, variant, object;
  size_t faces = 0;
  int frames = 0;
  double fps_median = 0, fps_min = 0, fps_max = 0;
  double rel_default = 0;  // fps_median over the default renderer's on the same object, same run
  std::map<std::string, double> counters;
};

struct Options {
  int frames = 1000;
  std::string mesh;  // the LOD series' source mesh
  std::string gl = "osmesa";  // off-screen backend
  std::string output_dir;     // where suites write extra files (CSV, plots): beside the JSON
  std::vector<std::string> photos;  // turntable: real photo folders to measure (every other photo held out)
  double minutes = 1;               // soak: how long the churn lasts
  bool even_turn = false;           // turntable --photos: take them as evenly spaced, not the turn found from the matches
};

// One object of the level-of-detail series, placed as in the study: thesis camera, one light,
// scaled to cover about 15.5% of a 620x500 window.
struct BenchObject {
  std::string name;  // "lod0".."lod5"
  SceneObject object;
  FrameState frame;
};

// The study's face counts for Deer0..Deer5 (SPEC G4).
inline const std::vector<size_t> kLodFaces = {578, 870, 1284, 2162, 5488, 10648};
inline constexpr int kWidth = 620, kHeight = 500;
inline constexpr double kTargetCoverage = 0.155;

class Harness {
 public:
  explicit Harness(const Options& options);
  const Options& options() const { return options_; }
  Canvas& canvas() { return *canvas_; }
  Context& context() { return *context_; }
  // The LOD series, built once on first use.
  std::vector<BenchObject>& lod_series();
  // Facts about the machine a suite found out (e.g. the browser's GL renderer), for the JSON.
  void set_machine(const std::string& key, const std::string& value) { machine_notes_[key] = value; }
  const std::map<std::string, std::string>& machine_notes() const { return machine_notes_; }

  // Times `frames` frames of `renderer` (after a short warm-up) drawing `object` over `backdrop`
  // (a flat grey when none is given, as the study drew) while it turns, finishing GL work each frame so the time is the frame's real cost.
  // Ends with one frame at the study's pose, so the renderer's counters describe that pose.
  // Fills fps fields and `frames`; the caller fills names and counters. Draws into `target`
  // when given (suites with their own image size), else the 620x500 canvas.
  Result time_frames(Renderer& renderer, const BenchObject& object, int frames, Canvas* target = nullptr, const Backdrop* backdrop = nullptr);

 private:
  Options options_;
  std::unique_ptr<Context> context_;
  std::unique_ptr<Canvas> canvas_;
  std::vector<BenchObject> lods_;
  std::map<std::string, std::string> machine_notes_;
};

using Suite = std::function<std::vector<Result>(Harness&)>;

// Registered suites by name, in the order they run for --suite all.
const std::vector<std::pair<std::string, Suite>>& suites();

std::vector<Result> run_default_suite(Harness& harness);
std::vector<Result> run_comic_suite(Harness& harness);
std::vector<Result> run_sketch_suite(Harness& harness);
std::vector<Result> run_hatching_suite(Harness& harness);
std::vector<Result> run_antialiasing_suite(Harness& harness);
std::vector<Result> run_painterly_suite(Harness& harness);
std::vector<Result> run_net_suite(Harness& harness);
std::vector<Result> run_face_suite(Harness& harness);
std::vector<Result> run_tween_suite(Harness& harness);
std::vector<Result> run_turntable_suite(Harness& harness);
std::vector<Result> run_web_suite(Harness& harness);
std::vector<Result> run_web_scene_suite(Harness& harness);
std::vector<Result> run_landmarks_suite(Harness& harness);
std::vector<Result> run_call_suite(Harness& harness);
std::vector<Result> run_abuse_suite(Harness& harness);
std::vector<Result> run_crash_suite(Harness& harness);
std::vector<Result> run_soak_suite(Harness& harness);
std::vector<Result> run_window_suite(Harness& harness);
std::vector<Result> run_rooms_suite(Harness& harness);

}  // namespace inkwire::bench
