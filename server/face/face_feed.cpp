#include "server/face/face_feed.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

namespace inkwire::server {
namespace {

using Clock = std::chrono::steady_clock;

// A source that fails this many frames in a row is given up (a camera unplugged, a folder of
// unreadable files); single bad frames are skipped.
constexpr int kMaxFailuresInARow = 10;

}  // namespace

FaceFeed::FaceFeed(FaceSourceConfig config) : config_(std::move(config)) {
  source_ = std::make_unique<VideoSource>(config_.source);
  std::optional<Image> first;
  if (config_.neutral.empty()) {
    first = source_->next();
    if (!first) throw Error("face source '" + config_.source + "' has no frames");
    neutral_ = *first;
  } else {
    neutral_ = load_image(config_.neutral);
  }
  // Faces in small frames are small: the detector then looks at twice the size.
  const int upsample = neutral_.width < 480 ? 1 : 0;
  coder_.emplace(FaceAnalyzerOptions{.detect_every = 5, .detect_width = 320, .upsample = upsample});
  landmarks_ = coder_->calibrate(neutral_);
}

FaceFeed::~FaceFeed() { stop(); }

void FaceFeed::start(Publish publish) {
  if (thread_.joinable()) throw Error("FaceFeed::start(): already started");
  thread_ = std::thread([this, publish = std::move(publish)] { run(publish); });
}

void FaceFeed::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool FaceFeed::wait_until(Clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  return !wake_.wait_until(lock, deadline, [&] { return stopping_; });
}

void FaceFeed::run(Publish publish) {
  const double fps = config_.fps > 0 ? config_.fps : source_->fps();
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / fps));
  const auto start = Clock::now();
  auto due = start;
  int failures = 0;
  long frames = 0, codes = 0;
  while (wait_until(due)) {
    std::optional<Image> frame;
    try {
      frame = source_->next();
      if (!frame && config_.loop && !source_->live()) {
        source_ = std::make_unique<VideoSource>(config_.source);
        frame = source_->next();
      }
      if (!frame) break;
      const double now = std::chrono::duration<double>(Clock::now() - start).count();
      if (const auto message = coder_->code(*frame, now)) {
        publish(*message);
        ++codes;
      }
      failures = 0;
      ++frames;
    } catch (const Error& e) {
      log_warn("face-frame-skipped", {{"source", config_.source}, {"reason", e.what()}});
      if (++failures >= kMaxFailuresInARow) {
        log(LogLevel::Error, "face-source-failed", {{"source", config_.source}, {"reason", "too many bad frames in a row"}});
        break;
      }
    }
    // A live camera paces itself (next() waits for the frame); a recording is paced here. When
    // analysis falls behind, the schedule starts again from now rather than rushing to catch up.
    due = source_->live() ? Clock::now() : std::max(due + period, Clock::now() - period);
  }
  log_info("face-source-ended", {{"source", config_.source}, {"frames", frames}, {"codes", codes},
                                 {"bytes", coder_->stream().bytes()}});
}

}  // namespace inkwire::server
