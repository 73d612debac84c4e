#pragma once
// What a call member hears (SPEC F9): every member's Opus packets decoded and mixed on this
// member's own clock, each member's clock mapped to it by its quickest packets' arrival plus a
// jitter delay, so packets that come early or bunched play at their time. A late packet raises
// its member's delay (playout_delay.hpp) and plays; one later than the largest delay is dropped
// (counted), never played late. The same mapping tells when a face code stamped on a member's
// clock is due, so mouths move with the sound. Single-threaded.
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "client/call/playout_delay.hpp"
#include "client/call/voice_codec.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class CallAudio {
 public:
  using Clock = std::chrono::steady_clock;
  explicit CallAudio(Clock::time_point start) : start_(start) {}

  void add(const protocol::VoiceFrame& frame, Clock::time_point arrived);
  // The mixed sound from where the last call ended up to `until` (this member's clock).
  std::vector<float> take(Clock::time_point until);
  // When `member`'s moment `time_ms` plays here; nothing before its first packet.
  std::optional<Clock::time_point> local_time(uint16_t member, uint32_t time_ms) const;

  uint64_t late() const { return late_; }        // packets dropped for coming after their time
  uint64_t played() const { return played_; }    // packets mixed in
  uint64_t skipped() const { return skipped_; }  // packets not played as the offset caught up with the quickest

 private:
  struct Member {
    VoiceDecoder decoder;
    VoiceClock clock;                // its mapping to local ms (since start_)
    std::optional<uint32_t> next_ms; // where the member's next packet should start, for concealing gaps
  };

  Clock::time_point start_;
  std::map<uint16_t, std::unique_ptr<Member>> members_;
  int64_t mixed_until_ = 0;    // samples since start_ handed out by take()
  std::vector<float> ahead_;   // mixed samples from mixed_until_ on
  uint64_t late_ = 0, played_ = 0, skipped_ = 0;
};

}  // namespace inkwire
