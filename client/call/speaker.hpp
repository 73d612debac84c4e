#pragma once
// A call's sound out of this machine's speaker (SPEC F9), through PortAudio's default output at
// 48 kHz mono: the window hands it what CallAudio says is due each frame. Without a device (a
// server, this build machine) there is nothing to open and the reason says so.
#include <span>
#include <string>

namespace inkwire {

class Speaker {
 public:
  Speaker();  // never throws: reason() says why there is no sound
  ~Speaker();
  Speaker(const Speaker&) = delete;
  Speaker& operator=(const Speaker&) = delete;

  bool open() const { return stream_ != nullptr; }
  const std::string& reason() const { return reason_; }
  // Plays `samples` after what is queued; what does not fit in the device's buffer is dropped
  // (a late frame is worth nothing).
  void play(std::span<const float> samples);

 private:
  void* stream_ = nullptr;
  bool initialised_ = false;
  std::string reason_;
};

}  // namespace inkwire
