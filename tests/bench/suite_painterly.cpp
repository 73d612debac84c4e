// Suite "painterly" (SPEC P10, the study's table 18 and figure 66): fps against brush count and
// against LOD, the reference capture's cost, the oil-filter baseline, and the visible and
// respawned brush fractions over time at several rotation speeds (CSV plus a plot image).
#include <cstdio>
#include <fstream>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <opencv2/imgproc.hpp>

#include "bench_harness.hpp"
#include "client/gl/gl.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/painterly/reference_capture.hpp"
#include "client/render/styles.hpp"

namespace inkwire::bench {

namespace {

// The capture alone (default renderer into the object's rectangle, read back): what painting
// costs before a brush moves.
class CaptureOnly final : public Renderer {
 public:
  CaptureOnly() { capture_.use_renderer("default"); }
  void configure(const StyleParams&) override {}
  void prepare(const SceneObject& object) override { capture_.prepare(object); }
  void draw(const FrameState& frame) override { capture_.capture(frame); }

 private:
  ReferenceCapture capture_;
};

Result timed(Harness& harness, Renderer& renderer, const BenchObject& object, int frames, const std::string& name,
             const std::string& variant, double default_fps) {
  renderer.prepare(object.object);
  Result r = harness.time_frames(renderer, object, frames);
  r.suite = "painterly";
  r.renderer = name;
  r.variant = variant;
  r.rel_default = default_fps > 0 ? r.fps_median / default_fps : 1.0;
  for (const auto& [key, value] : renderer.counters()) r.counters[key] = value;
  return r;
}

struct FractionSeries {
  double degrees;
  std::vector<double> visible, respawned;
};

// Brushes scattered afresh, then the object turning `degrees` per frame about its vertical axis.
FractionSeries fractions_over_time(Harness& harness, const BenchObject& object, double degrees, int frames) {
  auto painter = make_renderer("painterly", {"brushes=3000", "settle=0"});
  painter->prepare(object.object);
  const Backdrop clear(BackdropSpec::parse("#d9dde3"));
  FractionSeries series{degrees, {}, {}};
  FrameState frame = object.frame;
  for (int i = 0; i < frames; ++i) {
    frame.frame = i;
    frame.model = glm::rotate(glm::mat4(1.0f), float(glm::radians(degrees * i)), glm::vec3(0, 1, 0)) * object.frame.model;
    harness.canvas().bind();
    clear.draw();
    painter->draw(frame);
    const auto c = painter->counters();
    series.visible.push_back(c.at("visible_fraction"));
    series.respawned.push_back(c.at("respawn_fraction"));
  }
  return series;
}

void write_csv(const std::vector<FractionSeries>& all, const std::string& path) {
  std::ofstream out(path);
  out << "frame";
  for (const auto& s : all) out << ",visible_" << s.degrees << "deg,respawned_" << s.degrees << "deg";
  out << "\n";
  for (size_t f = 0; f < all.front().visible.size(); ++f) {
    out << f;
    for (const auto& s : all) out << "," << s.visible[f] << "," << s.respawned[f];
    out << "\n";
  }
}

// Visible fraction (thick) and respawned fraction (thin, scaled x10) per frame, one colour per speed.
void write_plot(const std::vector<FractionSeries>& all, const std::string& path) {
  const int w = 900, h = 500, left = 60, right = 20, top = 64, bottom = 50;
  cv::Mat plot(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar axis(60, 60, 60);
  const cv::Scalar colours[] = {{200, 80, 30}, {40, 160, 40}, {30, 120, 230}, {160, 40, 160}};
  auto px = [&](double frame, double value) {
    return cv::Point(left + int(frame / double(all.front().visible.size() - 1) * (w - left - right)), top + int((1.0 - value) * (h - top - bottom)));
  };
  for (int i = 0; i <= 10; ++i) {
    const cv::Point a = px(0, i / 10.0), b = px(double(all.front().visible.size() - 1), i / 10.0);
    cv::line(plot, a, b, cv::Scalar(225, 225, 225), 1);
    cv::putText(plot, std::to_string(i * 10) + "%", {4, a.y + 4}, cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1, cv::LINE_AA);
  }
  cv::rectangle(plot, px(0, 1), px(double(all.front().visible.size() - 1), 0), axis, 1);
  cv::putText(plot, "frame", {w / 2 - 20, h - 14}, cv::FONT_HERSHEY_SIMPLEX, 0.5, axis, 1, cv::LINE_AA);
  for (size_t f = 0; f < all.front().visible.size(); f += 50)
    cv::putText(plot, std::to_string(f), {px(double(f), 0).x - 8, h - bottom + 18}, cv::FONT_HERSHEY_SIMPLEX, 0.4, axis, 1, cv::LINE_AA);
  cv::putText(plot, "visible brushes (thick) and respawns x10 (thin), 3000 brushes", {left, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.55, axis, 1, cv::LINE_AA);
  for (size_t k = 0; k < all.size(); ++k) {
    const FractionSeries& s = all[k];
    for (size_t f = 1; f < s.visible.size(); ++f) {
      cv::line(plot, px(double(f - 1), s.visible[f - 1]), px(double(f), s.visible[f]), colours[k % 4], 2, cv::LINE_AA);
      cv::line(plot, px(double(f - 1), std::min(1.0, 10 * s.respawned[f - 1])), px(double(f), std::min(1.0, 10 * s.respawned[f])), colours[k % 4], 1, cv::LINE_AA);
    }
    char label[64];
    std::snprintf(label, sizeof label, "%g deg/frame", s.degrees);
    cv::putText(plot, label, {left + int(k) * 150, 50}, cv::FONT_HERSHEY_SIMPLEX, 0.5, colours[k % 4], 1, cv::LINE_AA);
  }
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Vec3b c = plot.at<cv::Vec3b>(y, x);
      uint8_t* p = image.at(x, y);
      p[0] = c[2], p[1] = c[1], p[2] = c[0], p[3] = 255;  // OpenCV keeps BGR
    }
  save_image(image, path, false);
}

double mean_of_last(const std::vector<double>& v, size_t n) {
  double sum = 0;
  for (size_t i = v.size() - n; i < v.size(); ++i) sum += v[i];
  return sum / double(n);
}

}  // namespace

std::vector<Result> run_painterly_suite(Harness& harness) {
  const int frames = std::max(200, harness.options().frames / 5);  // SPEC G4: at least 200
  std::vector<Result> results;
  std::vector<BenchObject>& lods = harness.lod_series();
  BenchObject& middle = lods[3];  // 2162 faces, the study's mid-size deer

  // Against brush count, on one object.
  auto reference = make_renderer("default");
  const Result base = timed(harness, *reference, middle, frames, "default", "", 0);
  results.push_back(base);
  CaptureOnly capture;
  results.push_back(timed(harness, capture, middle, frames, "painterly", "capture", base.fps_median));
  for (const int brushes : {1, 100, 1000, 2000, 3000, 4000, 10000}) {
    auto painter = make_renderer("painterly", {"brushes=" + std::to_string(brushes)});
    results.push_back(timed(harness, *painter, middle, frames, "painterly", "brushes=" + std::to_string(brushes), base.fps_median));
    std::fprintf(stderr, "inkwire-bench: painterly %d brushes done\n", brushes);
  }
  // Every shipped look at its own brush count: what a medium's glazes, wet edges and glow cost.
  for (const std::string style : {"impressionist", "pointillist", "watercolour", "neon", "sepia-study"}) {
    auto painter = make_renderer("painterly", {"style=" + style});
    results.push_back(timed(harness, *painter, middle, frames, "painterly", "style=" + style, base.fps_median));
  }
  auto oil = make_renderer("oil-filter");
  results.push_back(timed(harness, *oil, middle, std::min(frames, 50), "oil-filter", "radius=5", base.fps_median));

  // Against LOD, at 3000 brushes.
  for (BenchObject& object : lods) {
    if (&object == &middle) continue;
    auto def = make_renderer("default");
    const Result d = timed(harness, *def, object, frames, "default", "", 0);
    results.push_back(d);
    auto painter = make_renderer("painterly", {"brushes=3000"});
    results.push_back(timed(harness, *painter, object, frames, "painterly", "brushes=3000", d.fps_median));
  }

  // Visible and respawned fractions over time (the study's figure 66).
  std::vector<FractionSeries> series;
  for (const double degrees : {0.0, 2.0, 10.0, 30.0}) {
    series.push_back(fractions_over_time(harness, middle, degrees, 200));
    const FractionSeries& s = series.back();
    Result r;
    r.suite = "painterly";
    r.renderer = "painterly";
    r.variant = "degrees=" + std::to_string(int(degrees));
    r.object = middle.name;
    r.faces = middle.object.mesh.face_count();
    r.frames = 200;
    r.counters = {{"brushes", 3000},
                  {"degrees_per_frame", degrees},
                  {"visible_fraction", mean_of_last(s.visible, 100)},
                  {"visible_fraction_min", *std::min_element(s.visible.begin() + 100, s.visible.end())},
                  {"visible_fraction_first", s.visible.front()},
                  {"respawn_fraction", mean_of_last(s.respawned, 100)},
                  {"respawn_fraction_max", *std::max_element(s.respawned.begin(), s.respawned.end())}};
    results.push_back(r);
  }
  const std::string dir = harness.options().output_dir.empty() ? "." : harness.options().output_dir;
  write_csv(series, dir + "/painterly_fractions.csv");
  write_plot(series, dir + "/painterly_fractions.png");
  std::fprintf(stderr, "inkwire-bench: wrote %s/painterly_fractions.csv and .png\n", dir.c_str());
  return results;
}

}  // namespace inkwire::bench
