#pragma once
// A conference session's speaker on the server (SPEC F1-F4): frames from a camera, video or
// image sequence are analysed on a thread of their own, so the I/O thread keeps serving every
// client at its own pace; each expression code the pipeline emits is handed to `publish`, which
// the server points at its I/O thread. Recorded sources play in real time (and loop if asked),
// as a camera would deliver them.
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "common/video_source.hpp"
#include "server/config.hpp"
#include "server/face/face_coder.hpp"

namespace inkwire::server {

class FaceFeed {
 public:
  using Publish = std::function<void(const protocol::ExpressionCode&)>;

  // Opens the source and calibrates the speaker from the neutral photo (or, without one, the
  // source's first frame). Throws inkwire::Error with the reason (no source, no face, no model).
  explicit FaceFeed(FaceSourceConfig config);
  ~FaceFeed();  // stops
  FaceFeed(const FaceFeed&) = delete;
  FaceFeed& operator=(const FaceFeed&) = delete;

  // What the receivers need once: the neutral photo and its landmarks.
  const Image& neutral() const { return neutral_; }
  const FaceLandmarks& landmarks() const { return landmarks_; }

  // Starts analysing; `publish` is called on the feed's thread.
  void start(Publish publish);
  // Ends the thread (within one frame's analysis) and waits for it.
  void stop();

 private:
  void run(Publish publish);
  // Sleeps until `deadline` or stop(); false when stopped.
  bool wait_until(std::chrono::steady_clock::time_point deadline);

  FaceSourceConfig config_;
  std::unique_ptr<VideoSource> source_;
  std::optional<FaceCoder> coder_;  // made once the frame size is known
  Image neutral_;
  FaceLandmarks landmarks_{};
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
};

}  // namespace inkwire::server
