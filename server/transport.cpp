#include "server/transport.hpp"

#include <asio/experimental/as_tuple.hpp>

#include "common/log.hpp"
#include "protocol/framing.hpp"

namespace inkwire::server {
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

}  // namespace

std::string peer_of(const asio::ip::tcp::socket& socket) {
  std::error_code ec;
  const auto endpoint = socket.remote_endpoint(ec);
  return ec ? "unknown" : endpoint.address().to_string() + ":" + std::to_string(endpoint.port());
}

TcpTransport::TcpTransport(ByteStream stream) : stream_(std::move(stream)), peer_(peer_of(stream_.socket())) {
  std::error_code ec;
  stream_.socket().set_option(asio::ip::tcp::no_delay(true), ec);  // control messages are tiny: no Nagle delay
}

asio::awaitable<std::error_code> TcpTransport::read_frame(protocol::Bytes& frame) {
  frame.resize(protocol::kHeaderBytes);
  auto [ec, n] = co_await asio::async_read(stream_, asio::buffer(frame), no_throw);
  if (ec) co_return ec;
  // The length is checked here, before the payload is sized.
  const protocol::FrameHeader header = protocol::parse_header(frame.data());
  frame.resize(protocol::kHeaderBytes + header.length);
  auto [ec2, n2] = co_await asio::async_read(stream_, asio::buffer(frame.data() + protocol::kHeaderBytes, header.length), no_throw);
  co_return ec2;
}

asio::awaitable<std::error_code> TcpTransport::write_frames(const std::deque<Outgoing>& frames) {
  buffers_.clear();
  for (const Outgoing& o : frames) buffers_.push_back(asio::buffer(*o.frame));
  auto [ec, n] = co_await asio::async_write(stream_, buffers_, no_throw);
  co_return ec;
}

void secure_then(asio::ip::tcp::socket socket, std::shared_ptr<asio::ssl::context> tls, std::chrono::milliseconds timeout,
                 std::function<void(ByteStream)> ready) {
  if (!tls) return ready(ByteStream(std::move(socket)));
  const std::string peer = peer_of(socket);
  auto stream = std::make_shared<ByteStream>(std::move(socket), *tls);
  auto timer = std::make_shared<asio::steady_timer>(stream->get_executor(), timeout);
  timer->async_wait([stream](std::error_code ec) {
    if (!ec) stream->close();  // the handshake below then fails
  });
  stream->tls_stream()->async_handshake(asio::ssl::stream_base::server, [stream, timer, peer, tls, ready = std::move(ready)](std::error_code ec) {
    timer->cancel();
    if (ec) {
      log_warn("tls-handshake-failed", {{"peer", peer}, {"reason", ec.message()}});
      stream->close();
      return;
    }
    ready(std::move(*stream));
  });
}

asio::awaitable<void> accept_connections(asio::ip::tcp::acceptor& acceptor, const bool& stopping, const char* failure_event,
                                         std::function<void(asio::ip::tcp::socket)> accepted) {
  while (!stopping) {
    auto [ec, socket] = co_await acceptor.async_accept(no_throw);
    if (ec) {
      if (stopping) break;
      log_warn(failure_event, {{"reason", ec.message()}});
      asio::steady_timer pause(acceptor.get_executor(), std::chrono::milliseconds(100));
      co_await pause.async_wait(no_throw);
      continue;
    }
    accepted(std::move(socket));
  }
}

}  // namespace inkwire::server
