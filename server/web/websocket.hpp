#pragma once
// The WebSocket transport (RFC 6455, protocol/SPEC.md "Transport"): after the HTTP upgrade
// (http_server.hpp), each protocol frame travels as one binary WebSocket message. Messages are
// reassembled from fragments up to the protocol's frame limit, checked before anything is
// read; a text message, an unmasked client frame, a message over the limit or one that is not
// exactly one protocol frame is malformed. A Ping is answered with a Pong carrying its data; a
// Close is echoed with its status code and ends the connection; a connection the server ends
// gets a Close with a code that says why (1002 protocol error, 1009 too big, 1008 policy,
// 1001 going away). Control frames are written between, never inside, the writer's messages.
#include <array>
#include <string>
#include <vector>

#include "server/transport.hpp"

namespace inkwire::server {

class WebSocketTransport final : public Transport {
 public:
  // `already_read`: bytes that came after the upgrade request, the start of the first frames.
  WebSocketTransport(ByteStream stream, std::string already_read);
  asio::awaitable<std::error_code> read_frame(protocol::Bytes& frame) override;
  asio::awaitable<std::error_code> write_frames(const std::deque<Outgoing>& frames) override;
  asio::awaitable<void> goodbye(protocol::ErrorCode error, const std::string& reason) override;
  void close() override { stream_.close(); }
  std::string peer() const override { return peer_; }
  std::string name() const override { return stream_.tls() ? "websocket-tls" : "websocket"; }
  asio::any_io_executor executor() override { return stream_.get_executor(); }

 private:
  // Fills `out` with exactly out.size() bytes, the leftover of the upgrade first.
  asio::awaitable<std::error_code> read_exactly(uint8_t* out, size_t size);
  // One writer at a time: the connection's writer and the reader's Pongs and Closes take turns.
  asio::awaitable<void> lock_writes();
  void unlock_writes();
  // A Close with `code` and `reason` (at most 123 bytes), once.
  asio::awaitable<void> send_close(uint16_t code, const std::string& reason);

  ByteStream stream_;
  std::string pending_;  // read with the upgrade request, not yet consumed
  std::string peer_;
  std::vector<std::array<uint8_t, 10>> headers_;
  std::vector<asio::const_buffer> buffers_;
  bool writing_ = false, close_sent_ = false;
  asio::steady_timer write_free_;  // cancelled whenever writing_ clears, waking who waits for it
  uint16_t close_code_ = 0;        // a code the reader chose for the Close (1009 for a message too big)
};

// The Sec-WebSocket-Accept value for a client's Sec-WebSocket-Key.
std::string websocket_accept(const std::string& key);

// The header of one unmasked (server-to-client) frame of `opcode` carrying `size` bytes: the
// bytes to send before the payload, in `out`; returns how many.
size_t websocket_frame_header(uint8_t opcode, uint64_t size, std::array<uint8_t, 10>& out);

}  // namespace inkwire::server
