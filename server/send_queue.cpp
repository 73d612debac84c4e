#include "server/send_queue.hpp"

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
