// inkwire-bench --suite face (SPEC F6): analysis speed at 640x480 (detector, landmark model,
// the whole pipeline with detection every 5th frame and tracking between), capture-to-code
// latency, and the bytes the expression stream sends per second at 15 and 30 fps against the
// same clip encoded by x264 at its lowest sensible quality (CRF 40, "veryslow"); and the face
// renderer's frame time (SPEC F20: at most 1.5x before), a call's tile at 640x480 drawn each frame
// in the plain, comic and painterly looks: `draw,codes,STYLE` as faces were drawn before poses
// (one code at a time, the head still), against `draw,pose+layers,STYLE` (the head turning, layers
// mixed), as a ratio to the first in the same run.
//
// The clip: no face video is packaged, so a speaker is synthesised from libdlib19.1's example
// photo by the face reconstruction, following a script of expressions (each held about 0.7 s),
// and placed on a 640x480 frame.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>


#include "bench_harness.hpp"
#include "client/gl/canvas.hpp"
#include "client/gl/gl.hpp"
#include "client/output/frame_writer.hpp"
#include "client/render/face/conference_view.hpp"
#include "client/render/face/face_reconstructor.hpp"
#include "common/error.hpp"
#include "server/face/face_coder.hpp"

namespace inkwire::bench {
namespace {

const std::filesystem::path kPhoto = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";
constexpr int kWidth = 640, kHeight = 480;
constexpr double kClipSeconds = 12.0;

// The photo scaled to the frame's height, centred on grey.
Image framed(const Image& photo) {
  const int w = int(double(photo.width) * kHeight / photo.height);
  const Image scaled = resized(photo, w, kHeight);
  Image out(kWidth, kHeight);
  for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = i % 4 == 3 ? 255 : 110;
  for (int y = 0; y < kHeight; ++y)
    std::copy_n(&scaled.pixels[size_t(y) * size_t(w) * 4], size_t(w) * 4, &out.pixels[(size_t(y) * kWidth + size_t((kWidth - w) / 2)) * 4]);
  return out;
}

// The speaker clip at `fps`: expressions from a fixed script, each tweened in as on a client.
std::vector<Image> speaker_clip(const Image& frame, const FaceLandmarks& landmarks, double fps) {
  const ExpressionState script[] = {{Expression::Neutral, 0},     {Expression::Smile, 200},      {Expression::Neutral, 0},
                                    {Expression::Surprise, 255},  {Expression::VisemeOpen, 180}, {Expression::VisemeRound, 200},
                                    {Expression::Neutral, 0},     {Expression::Laugh, 220},      {Expression::EyesClosed, 255},
                                    {Expression::Neutral, 0},     {Expression::WinkLeft, 255},   {Expression::VisemeWide, 200},
                                    {Expression::Frown, 255},     {Expression::Neutral, 0},      {Expression::Sad, 255},
                                    {Expression::Neutral, 0},     {Expression::Surprise, 160}};
  FaceReconstructor actor(frame, landmarks);
  std::vector<Image> clip;
  const int frames = int(kClipSeconds * fps);
  const double step = kClipSeconds / double(std::size(script));
  int shown = -1;
  for (int i = 0; i < frames; ++i) {
    const double t = double(i) / fps;
    const int k = std::min(int(t / step), int(std::size(script)) - 1);
    if (k != shown) actor.set_expression(script[k], t), shown = k;
    actor.render(t);
    clip.push_back(actor.read());  // opaque: the warped photo covers every pixel
  }
  return clip;
}

// x264's size for the clip: bytes per second of the encoded stream.
double x264_bytes_per_second(const std::vector<Image>& clip, double fps, const std::string& dir) {
  const std::string out = (std::filesystem::path(dir.empty() ? "." : dir) / "face-clip-x264.mp4").string();
  FrameWriter writer(out, int(clip.size()), int(fps), false, {.crf = 40, .preset = "veryslow"});
  for (const Image& f : clip) writer.write(f);
  writer.close();
  const double bytes = double(std::filesystem::file_size(out));
  std::filesystem::remove(out);
  return bytes / (double(clip.size()) / fps);
}

// Milliseconds per frame of a call's tile drawing `script` (one state per tween), each frame
// finished by the driver.
template <typename State>
std::vector<double> draw_times(const Image& frame, const FaceLandmarks& landmarks, const std::string& style, const std::vector<State>& script, int frames) {
  ConferenceView view(frame, landmarks);
  view.set_style(style, {});
  Canvas canvas(kWidth, kHeight);
  const FramebufferBinding restore;
  canvas.bind();
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const double t = double(i) / 30.0;
    if (i % 3 == 0) view.set_face(script[size_t(i / 3) % script.size()]);  // a new face every 100 ms, as a call's stream sends
    const auto start = std::chrono::steady_clock::now();
    view.draw(canvas.size(), t);
    gl::glFinish();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return ms;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

Result row(const std::string& variant, const std::vector<double>& ms) {
  Result r;
  r.suite = r.renderer = "face";
  r.variant = variant;
  r.object = "640x480";
  r.frames = int(ms.size());
  auto sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  r.fps_median = 1000.0 / median(ms);
  r.fps_min = 1000.0 / sorted.back();
  r.fps_max = 1000.0 / sorted.front();
  r.counters["fps"] = r.fps_median;
  r.counters["latency_ms"] = median(ms);
  return r;
}

}  // namespace

std::vector<Result> run_face_suite(Harness& harness) {
  if (!std::filesystem::exists(kDefaultFaceModel) || !std::filesystem::exists(kPhoto)) {
    std::fprintf(stderr, "inkwire-bench: face suite skipped: needs libdlib-data and libdlib19.1's example faces\n");
    return {};
  }
  harness.context();
  const Image frame = framed(load_image(kPhoto));
  FaceAnalyzer probe({.detect_every = 1, .detect_width = 320, .upsample = 0});
  const auto face = probe.analyse(frame);
  if (!face) throw Error("face suite: no face in the benchmark frame");

  std::vector<Result> results;
  const std::vector<Image> clip30 = speaker_clip(frame, face->landmarks, 30.0);
  const int frames = std::min<int>(int(clip30.size()), std::max(harness.options().frames, 30));
  using Clock = std::chrono::steady_clock;
  auto ms_since = [](Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); };

  // Detector alone (reduced to 320 wide, as the pipeline runs it) and landmark model alone.
  std::vector<double> detect_ms, landmark_ms, total_ms;
  for (int i = 0; i < frames; ++i) {
    auto t = Clock::now();
    const auto boxes = probe.detect(clip30[size_t(i)]);
    detect_ms.push_back(ms_since(t));
    if (boxes.empty()) continue;
    t = Clock::now();
    probe.landmarks_in(clip30[size_t(i)], boxes.front());
    landmark_ms.push_back(ms_since(t));
  }
  // The renderer: faces before poses (one code, the head still) and now (pose and layers).
  {
    std::vector<FaceState> codes, posed;
    for (const auto& [code, intensity] : std::vector<std::pair<Expression, int>>{
             {Expression::Smile, 200}, {Expression::VisemeOpen, 180}, {Expression::Neutral, 0}, {Expression::Surprise, 255}, {Expression::EyesClosed, 255}})
      codes.push_back({.layers = layers_of({code, uint8_t(intensity)}, shipped_templates())});
    for (size_t i = 0; i < 12; ++i) {
      FaceState s = codes[i % codes.size()];
      s.layers.eye_left = s.layers.eye_right = i % 4 == 3 ? 0 : 100;
      s.pose = {.yaw = 25.0f * float(int(i % 5) - 2) / 2, .pitch = 10.0f * float(int(i % 3) - 1), .roll = 8.0f * float(int(i % 4) - 2) / 2};
      posed.push_back(s);
    }
    constexpr int kDraws = 150;  // five seconds of call at 30 fps
    for (const char* style : {"default", "comic", "painterly"}) {
      Result before = row(std::string("draw,codes,") + style, draw_times(frame, face->landmarks, style, codes, kDraws));
      const double reference = before.counters["frame_ms"] = before.counters["latency_ms"];
      before.counters["ratio_to_codes"] = 1;
      results.push_back(before);
      Result now = row(std::string("draw,pose+layers,") + style, draw_times(frame, face->landmarks, style, posed, kDraws));
      now.counters["frame_ms"] = now.counters["latency_ms"];
      now.counters["ratio_to_codes"] = now.counters["frame_ms"] / reference;
      results.push_back(now);
    }
  }
  results.push_back(row("detect", detect_ms));
  results.push_back(row("landmarks", landmark_ms));

  // The whole pipeline at 15 and 30 fps of clip: time per frame (capture to code) and bytes sent.
  for (double fps : {30.0, 15.0}) {
    const std::vector<Image> clip = fps == 30.0 ? clip30 : speaker_clip(frame, face->landmarks, fps);
    FaceCoder coder({.detect_every = 5, .detect_width = 320, .upsample = 0});
    coder.calibrate(frame);
    total_ms.clear();
    for (size_t i = 0; i < clip.size(); ++i) {
      const auto t = Clock::now();
      coder.code(clip[i], double(i) / fps);
      total_ms.push_back(ms_since(t));
    }
    Result r = row("total,fps=" + std::to_string(int(fps)), total_ms);
    double sum = 0;
    for (double ms : total_ms) sum += ms;
    r.counters["fps"] = 1000.0 * double(total_ms.size()) / sum;  // throughput: detection frames included
    r.counters["bytes_per_second"] = double(coder.stream().bytes()) / kClipSeconds;
    r.counters["bits_per_second"] = 8.0 * r.counters["bytes_per_second"];
    r.counters["messages"] = double(coder.stream().messages());
    r.counters["x264_bytes_per_second"] = x264_bytes_per_second(clip, fps, harness.options().output_dir);
    r.counters["x264_ratio"] = r.counters["x264_bytes_per_second"] / std::max(r.counters["bytes_per_second"], 1e-9);
    results.push_back(r);
  }
  return results;
}

}  // namespace inkwire::bench
