#pragma once
// How a connection's protocol frames travel: as they are over TCP,
// or one frame per binary WebSocket message (server/web/). The connection's logic, its
// sessions and its send queue never know which.
#include <chrono>
#include <deque>
#include <memory>
#include <functional>
#include <string>
#include <system_error>

#include <asio.hpp>

#include "protocol/net/byte_stream.hpp"
#include "protocol/messages.hpp"
#include "server/send_queue.hpp"

namespace inkwire::server {

class Transport {
 public:
  virtual ~Transport() = default;
  // The next whole frame (header and payload), its length checked against the protocol's limit
  // before anything is allocated. Throws protocol::ProtocolError when what arrives is malformed
  // for this transport; returns an error code when the peer has gone.
  virtual asio::awaitable<std::error_code> read_frame(protocol::Bytes& frame) = 0;
  // Writes the frames in order, gathered where the transport can.
  virtual asio::awaitable<std::error_code> write_frames(const std::deque<Outgoing>& frames) = 0;
  // The transport's own last word before the connection closes for `error` (a WebSocket Close
  // frame with its status code); nothing over TCP, where the error message is the last word.
  virtual asio::awaitable<void> goodbye(protocol::ErrorCode error, const std::string& reason) {
    (void)error, (void)reason;
    co_return;
  }
  virtual void close() = 0;
  virtual std::string peer() const = 0;
  virtual std::string name() const = 0;  // "tcp", "websocket": for logs and metrics
  virtual asio::any_io_executor executor() = 0;
};

// Frames as they are, over TCP, plain or TLS (protocol/SPEC.md "Framing").
class TcpTransport final : public Transport {
 public:
  explicit TcpTransport(ByteStream stream);
  asio::awaitable<std::error_code> read_frame(protocol::Bytes& frame) override;
  asio::awaitable<std::error_code> write_frames(const std::deque<Outgoing>& frames) override;
  void close() override { stream_.close(); }
  std::string peer() const override { return peer_; }
  std::string name() const override { return stream_.tls() ? "tls" : "tcp"; }
  asio::any_io_executor executor() override { return stream_.get_executor(); }

 private:
  ByteStream stream_;
  std::string peer_;
  std::vector<asio::const_buffer> buffers_;
};

// "address:port" of a socket's peer, or "unknown".
std::string peer_of(const asio::ip::tcp::socket& socket);

// Hands an accepted socket on as a stream: at once for plain TCP; with `tls`, once its TLS
// handshake is done within `timeout`. A peer that does not complete it (plain TCP on a TLS
// port, a bad certificate request, silence) is logged and let go; nobody else waits for it.
void secure_then(asio::ip::tcp::socket socket, std::shared_ptr<asio::ssl::context> tls, std::chrono::milliseconds timeout,
                 std::function<void(ByteStream)> ready);

// Accepts connections until `stopping` turns true, handing each socket to `accepted`. A failed
// accept (out of descriptors and the like) is logged as `failure_event` and retried after a
// breath; the clients already served carry on. Shared by the TCP and HTTP listeners.
asio::awaitable<void> accept_connections(asio::ip::tcp::acceptor& acceptor, const bool& stopping, const char* failure_event,
                                         std::function<void(asio::ip::tcp::socket)> accepted);

}  // namespace inkwire::server
