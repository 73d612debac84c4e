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

TcpTransport::TcpTransport(asio::ip::tcp::socket socket) : socket_(std::move(socket)), peer_(peer_of(socket_)) {
  std::error_code ec;
  socket_.set_option(asio::ip::tcp::no_delay(true), ec);  // control messages are tiny: no Nagle delay
}

asio::awaitable<std::error_code> TcpTransport::read_frame(protocol::Bytes& frame) {
  frame.resize(protocol::kHeaderBytes);
  auto [ec, n] = co_await asio::async_read(socket_, asio::buffer(frame), no_throw);
  if (ec) co_return ec;
  // The length is checked here, before the payload is sized.
  const protocol::FrameHeader header = protocol::parse_header(frame.data());
  frame.resize(protocol::kHeaderBytes + header.length);
  auto [ec2, n2] = co_await asio::async_read(socket_, asio::buffer(frame.data() + protocol::kHeaderBytes, header.length), no_throw);
  co_return ec2;
}

asio::awaitable<std::error_code> TcpTransport::write_frames(const std::deque<Outgoing>& frames) {
  buffers_.clear();
  for (const Outgoing& o : frames) buffers_.push_back(asio::buffer(*o.frame));
  auto [ec, n] = co_await asio::async_write(socket_, buffers_, no_throw);
  co_return ec;
}

void close_socket(asio::ip::tcp::socket& socket) {
  std::error_code ec;
  socket.shutdown(asio::ip::tcp::socket::shutdown_both, ec);
  socket.close(ec);
}

void TcpTransport::close() { close_socket(socket_); }

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
