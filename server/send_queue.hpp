#pragma once
// A client's outgoing queue (SPEC N4): bounded in bytes, and latest-wins for state messages
// (style, poses, expression, snapshot), so a reader that falls behind receives fewer, newer
// updates and never makes the server buffer without limit or wait for it. Voice is neither: it is
// never replaced, but a reader with kMaxWaitingVoice packets waiting loses the oldest. No
// sockets here: the connection's writer drains it.
#include <cstdint>
#include <deque>
#include <memory>

#include "protocol/messages.hpp"

namespace inkwire::server {

struct Outgoing {
  std::shared_ptr<const protocol::Bytes> frame;  // shared: one encoding per broadcast
  protocol::MessageType type;
};

class SendQueue {
 public:
  explicit SendQueue(size_t max_bytes) : max_bytes_(max_bytes) {}

  // Queues a frame. A state message replaces a queued one of its type. Returns false (and
  // queues nothing) when another message would take the queue over its byte limit: the peer is
  // too slow and should be told so and closed.
  bool push(std::shared_ptr<const protocol::Bytes> frame, protocol::MessageType type);
  // Everything queued, oldest first, leaving the queue empty.
  std::deque<Outgoing> take_all();

  bool empty() const { return entries_.empty(); }
  size_t bytes() const { return bytes_; }
  uint64_t replaced() const { return replaced_; }  // state messages overtaken before sending
  uint64_t voice_dropped() const { return voice_dropped_; }  // voice packets that waited too long
  static constexpr size_t kMaxWaitingVoice = 8;

 private:
  std::deque<Outgoing> entries_;
  size_t bytes_ = 0, max_bytes_;
  uint64_t replaced_ = 0, voice_dropped_ = 0;
};

}  // namespace inkwire::server
