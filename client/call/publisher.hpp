#pragma once
// What a call member sends of itself (SPEC F7-F9), from its own camera and microphone: the
// neutral photo once (given, or the camera's first frame), its face around where the server
// last found it (at most 15 pictures a second, 160 px; the whole frame scaled to 320 px until it
// is found) as VP8 video (SPEC F17) or, where asked, as separate JPEG crops, and Opus voice, all
// stamped on one clock. Camera and microphone are read
// on threads of their own, recorded sources (video, image folder, WAV) in real time as a device
// would deliver them; at their end the member stops publishing them. Muted sends no voice,
// camera off no crops. Camera pictures stay in memory.
#include <atomic>
#include <chrono>
#include <optional>
#include <string>
#include <thread>

#include "client/call/face_video_encoder.hpp"
#include "client/net/session_client.hpp"
#include "common/image.hpp"
#include "common/video_source.hpp"

namespace inkwire {

struct PublisherOptions {
  std::string camera;      // VideoSource spec (camera:N, a video, a folder of images); empty: none
  std::string microphone;  // "default" (the system's input through PortAudio) or a WAV file; empty: none
  std::string photo;       // the neutral photo; empty: the camera's first frame
  // 10 kbit/s: speech recognition of what came through stays with the original's (at 8 it fell
  // far behind) and a speaker costs a listener under 10 kbit/s in all; 60 ms packets: the
  // framing costs 2.4 kbit/s instead of 3.6 at 40 ms (docs/benchmarks.md, calls).
  int voice_bitrate = 10000;
  int voice_frame_ms = 60;
  double max_fps = 15;
  // The face as VP8 video (Vp8) or as separate JPEG crops (Jpeg: about 8 times the bits, for a
  // server that reads no video). 36 kbit/s: with voice and framing a publisher sends under 64.
  enum class Crops { Vp8, Jpeg } crops = Crops::Vp8;
  int video_bitrate = 36000;
};

class Publisher {
 public:
  // Opens the sources (throws inkwire::Error with the reason: no such camera, no microphone, a
  // file that is no video or WAV) and sends what this member publishes and its neutral photo.
  Publisher(SessionClient& client, PublisherOptions options);
  ~Publisher();  // stops both threads
  Publisher(const Publisher&) = delete;
  Publisher& operator=(const Publisher&) = delete;

  void set_muted(bool muted);
  void set_camera_off(bool off);
  bool muted() const { return muted_; }
  bool camera_off() const { return camera_off_; }
  uint64_t crops_sent() const { return crops_; }
  uint64_t voice_sent() const { return voices_; }
  uint64_t bytes_sent() const { return bytes_; }
  // The microphone's level over the latest packet, dB below full scale (a level meter).
  float level_db() const { return level_db_; }
  // Milliseconds on the publisher's clock (what crops and voice are stamped with), and when it began.
  uint32_t now_ms() const;
  std::chrono::steady_clock::time_point clock_start() const { return start_; }

 private:
  struct Microphone;
  void announce();
  void run_camera(Image first);
  void run_microphone();
  std::optional<protocol::FaceRegion> usable_region(const Image& frame) const;
  void send_crop(const Image& frame);
  void send_video(const Image& frame);
  // After the client rejoined (a new connection): the photo and what is published said again, and
  // the video starts with a key frame. Either thread may find it first; one says it.
  void say_again_if_rejoined();

  SessionClient& client_;
  PublisherOptions options_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<bool> stopping_{false}, muted_{false}, camera_off_{false}, camera_live_{false}, microphone_live_{false};
  std::atomic<uint64_t> crops_{0}, voices_{0}, bytes_{0};
  std::atomic<uint64_t> connection_said_{1};  // the client's connection this member last announced itself on
  std::vector<uint8_t> photo_jpeg_;           // the neutral photo as sent
  std::atomic<bool> video_restart_{false};
  std::atomic<float> level_db_{-100};
  std::unique_ptr<VideoSource> camera_source_;
  std::unique_ptr<Microphone> microphone_source_;
  // The face video, on the camera's thread only: its encoder (for the picture size it has now),
  // the crop it shows, its frames so far.
  std::unique_ptr<FaceVideoEncoder> video_encoder_;
  protocol::FaceRegion video_crop_;
  uint32_t video_sequence_ = 0;
  std::thread camera_, microphone_;
};

}  // namespace inkwire
