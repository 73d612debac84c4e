#include "bench_harness.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/coverage.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"
#include "common/lod.hpp"
#include "common/mesh_import.hpp"

namespace inkwire::bench {

Harness::Harness(const Options& options) : options_(options) {
  context_ = create_offscreen_context(kWidth, kHeight, options.gl);
  canvas_ = std::make_unique<Canvas>(kWidth, kHeight, 1);  // the study drew without antialiasing
}

std::vector<BenchObject>& Harness::lod_series() {
  if (!lods_.empty()) return lods_;
  const Mesh source = load_mesh(options_.mesh);
  auto reference = make_renderer("default");
  for (size_t i = 0; i < kLodFaces.size(); ++i) {
    Mesh lod = simplify_to_faces(source, kLodFaces[i]);
    normalise(lod, 10.0f);
    BenchObject b{"lod" + std::to_string(i), make_scene_object(std::move(lod)), {}};
    b.frame.camera = thesis_camera();
    b.frame.viewport = {kWidth, kHeight};
    b.frame.light_direction = default_light_direction(b.frame.camera);
    reference->prepare(b.object);
    const float scale = fit_scale_for_coverage(*reference, b.frame, *canvas_, kTargetCoverage);
    b.frame.model = glm::scale(glm::mat4(1.0f), glm::vec3(scale));
    lods_.push_back(std::move(b));
  }
  return lods_;
}

Result Harness::time_frames(Renderer& renderer, const BenchObject& object, int frames, Canvas* target, const Backdrop* backdrop) {
  Canvas& canvas = target ? *target : *canvas_;
  const Backdrop grey(BackdropSpec::parse("#d9dde3"));
  const Backdrop& clear = backdrop ? *backdrop : grey;
  // The object turns a full revolution every 1000 frames about its vertical axis, so every
  // frame's view-dependent work (orientation, silhouettes) is real work, as it is for a user
  // turning the object; counters are read at the study's pose.
  FrameState frame = object.frame;
  frame.backdrop = &clear;
  const glm::mat4 pose = object.frame.model;
  std::vector<double> seconds;
  seconds.reserve(size_t(frames));
  const int warm_up = std::min(20, frames);
  for (int i = -warm_up; i < frames; ++i) {
    frame.frame = i;
    frame.time_seconds = i / 60.0;
    frame.model = glm::rotate(glm::mat4(1.0f), float(i) * 2.0f * std::numbers::pi_v<float> / 1000.0f, glm::vec3(0, 1, 0)) * pose;
    const auto start = std::chrono::steady_clock::now();
    canvas.bind();
    clear.draw();
    renderer.draw(frame);
    gl::glFinish();
    const auto end = std::chrono::steady_clock::now();
    if (i >= 0) seconds.push_back(std::chrono::duration<double>(end - start).count());
  }
  gl::check_error("bench frame");
  frame.model = pose;  // leave the renderer's counters describing the study's pose
  canvas.bind();
  clear.draw();
  renderer.draw(frame);
  std::sort(seconds.begin(), seconds.end());
  Result r;
  r.object = object.name;
  r.faces = object.object.mesh.face_count();
  r.frames = frames;
  r.fps_median = 1.0 / seconds[seconds.size() / 2];
  r.fps_min = 1.0 / seconds.back();
  r.fps_max = 1.0 / seconds.front();
  r.counters["frame_ms_p99"] = 1000.0 * seconds[std::min(seconds.size() - 1, seconds.size() * 99 / 100)];
  return r;
}

const std::vector<std::pair<std::string, Suite>>& suites() {
  static const std::vector<std::pair<std::string, Suite>> all = {{"default", run_default_suite}, {"comic", run_comic_suite}, {"sketch", run_sketch_suite}, {"hatching", run_hatching_suite}, {"antialiasing", run_antialiasing_suite}, {"painterly", run_painterly_suite}, {"tween", run_tween_suite}, {"turntable", run_turntable_suite}, {"web", run_web_suite}, {"web-scene", run_web_scene_suite}, {"landmarks", run_landmarks_suite}, {"face", run_face_suite}, {"net", run_net_suite}, {"call", run_call_suite}, {"abuse", run_abuse_suite}, {"crash", run_crash_suite}, {"soak", run_soak_suite}, {"window", run_window_suite}, {"rooms", run_rooms_suite}};
  return all;
}

}  // namespace inkwire::bench
