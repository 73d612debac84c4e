#include "server/send_queue.hpp"

#include <algorithm>
#include <utility>

namespace inkwire::server {

bool SendQueue::push(std::shared_ptr<const protocol::Bytes> frame, protocol::MessageType type) {
  if (protocol::is_state(type)) {
    for (Outgoing& queued : entries_) {
      if (queued.type != type) continue;
      bytes_ = bytes_ - queued.frame->size() + frame->size();
      queued.frame = std::move(frame);
      ++replaced_;
      return true;
    }
  } else if (type == protocol::MessageType::VoiceFrame) {
    // Late voice is worth nothing: past a few packets waiting, the oldest goes (SPEC F12).
    size_t waiting = 0;
    for (const Outgoing& queued : entries_) waiting += queued.type == type;
    if (waiting >= kMaxWaitingVoice) {
      const auto oldest = std::find_if(entries_.begin(), entries_.end(), [&](const Outgoing& o) { return o.type == type; });
      bytes_ -= oldest->frame->size();
      entries_.erase(oldest);
      ++voice_dropped_;
    }
  } else if (bytes_ + frame->size() > max_bytes_) {
    return false;
  }
  bytes_ += frame->size();
  entries_.push_back({std::move(frame), type});
  return true;
}

std::deque<Outgoing> SendQueue::take_all() {
  bytes_ = 0;
  return std::exchange(entries_, {});
}

}  // namespace inkwire::server
