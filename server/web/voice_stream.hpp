#pragma once
// A call member's voice as one streamed HTTP response (protocol/SPEC.md "Voice route", SPEC F15):
// after the head, every voice frame relayed to the member is one chunk of a chunked body that
// never ends by itself. At most 8 frames wait (the oldest goes: late voice is of no use); the
// stream ends when the peer closes it, a write fails, or a write has waited for the idle
// deadline (a page that stopped reading). Its connection then sends voice on its own socket again.
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include <asio.hpp>

#include "protocol/messages.hpp"
#include "protocol/net/byte_stream.hpp"

namespace inkwire::server {

class VoiceStream : public std::enable_shared_from_this<VoiceStream> {
 public:
  static constexpr size_t kMaxWaiting = 8;  // as a connection's voice packets (SPEC F9)
  VoiceStream(ByteStream stream, std::chrono::steady_clock::duration stuck);
  // Writes the response head, then frames as they come; reads only to notice the peer leaving.
  void start(std::string head);
  void send(std::shared_ptr<const protocol::Bytes> frame);
  bool open() const { return open_; }
  void close();

 private:
  asio::awaitable<void> write_loop(std::string head);
  asio::awaitable<void> watch_peer();

  ByteStream stream_;
  std::chrono::steady_clock::duration stuck_;
  std::deque<std::shared_ptr<const protocol::Bytes>> waiting_;
  asio::steady_timer wake_;  // the writer sleeps on it; send() cancels it
  std::optional<std::chrono::steady_clock::time_point> writing_since_;
  bool open_ = true;
};

}  // namespace inkwire::server
