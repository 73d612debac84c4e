#include "server/web/websocket.hpp"

#include <cstring>

#include <asio/experimental/as_tuple.hpp>
#include <openssl/evp.h>
#include <openssl/sha.h>

#include "protocol/framing.hpp"

namespace inkwire::server {
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
constexpr uint8_t kContinuation = 0x0, kText = 0x1, kBinary = 0x2, kClose = 0x8, kPing = 0x9, kPong = 0xa;
// One protocol frame at most per message.
constexpr uint64_t kMaxMessage = protocol::kHeaderBytes + protocol::kMaxPayload;

}  // namespace

std::string websocket_accept(const std::string& key) {
  const std::string text = key + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";
  unsigned char digest[SHA_DIGEST_LENGTH];
  SHA1(reinterpret_cast<const unsigned char*>(text.data()), text.size(), digest);
  unsigned char base64[4 * ((SHA_DIGEST_LENGTH + 2) / 3) + 1];
  const int n = EVP_EncodeBlock(base64, digest, SHA_DIGEST_LENGTH);
  return std::string(reinterpret_cast<char*>(base64), size_t(n));
}

size_t websocket_frame_header(uint8_t opcode, uint64_t size, std::array<uint8_t, 10>& out) {
  out[0] = uint8_t(0x80 | opcode);  // FIN: every message in one frame
  if (size < 126) {
    out[1] = uint8_t(size);
    return 2;
  }
  if (size <= 0xffff) {
    out[1] = 126;
    out[2] = uint8_t(size >> 8), out[3] = uint8_t(size);
    return 4;
  }
  out[1] = 127;
  for (int i = 0; i < 8; ++i) out[size_t(2 + i)] = uint8_t(size >> (8 * (7 - i)));
  return 10;
}

WebSocketTransport::WebSocketTransport(ByteStream stream, std::string already_read)
    : stream_(std::move(stream)),
      pending_(std::move(already_read)),
      peer_(peer_of(stream_.socket())),
      write_free_(stream_.get_executor(), asio::steady_timer::time_point::max()) {
  std::error_code ec;
  stream_.socket().set_option(asio::ip::tcp::no_delay(true), ec);
}

asio::awaitable<std::error_code> WebSocketTransport::read_exactly(uint8_t* out, size_t size) {
  const size_t from_pending = std::min(size, pending_.size());
  std::memcpy(out, pending_.data(), from_pending);
  pending_.erase(0, from_pending);
  if (from_pending == size) co_return std::error_code();
  auto [ec, n] = co_await asio::async_read(stream_, asio::buffer(out + from_pending, size - from_pending), no_throw);
  co_return ec;
}

asio::awaitable<std::error_code> WebSocketTransport::read_frame(protocol::Bytes& frame) {
  frame.clear();
  bool in_message = false;
  for (;;) {
    uint8_t head[2];
    if (auto ec = co_await read_exactly(head, 2)) co_return ec;
    const bool fin = head[0] & 0x80, masked = head[1] & 0x80;
    const uint8_t opcode = head[0] & 0x0f;
    if (head[0] & 0x70) throw protocol::ProtocolError("WebSocket frame with reserved bits set");
    if (!masked) throw protocol::ProtocolError("unmasked WebSocket frame from a client");
    uint64_t size = head[1] & 0x7f;
    if (size >= 126) {
      uint8_t extended[8];
      const size_t bytes = size == 126 ? 2 : 8;
      if (auto ec = co_await read_exactly(extended, bytes)) co_return ec;
      size = 0;
      for (size_t i = 0; i < bytes; ++i) size = size << 8 | extended[i];
    }
    uint8_t mask[4];
    if (auto ec = co_await read_exactly(mask, 4)) co_return ec;
    const bool control = opcode & 0x8;
    if (control) {
      if (!fin || size > 125) throw protocol::ProtocolError("WebSocket control frame fragmented or over 125 bytes");
      uint8_t body[125];
      if (auto ec = co_await read_exactly(body, size_t(size))) co_return ec;
      for (size_t i = 0; i < size; ++i) body[i] ^= mask[i % 4];
      if (opcode == kClose) {
        // RFC 6455 5.5.1: echo the status code (none given: none echoed), then the connection ends.
        if (size == 1) throw protocol::ProtocolError("WebSocket Close with a one-byte body");
        co_await send_close(size >= 2 ? uint16_t(body[0] << 8 | body[1]) : 0, "");
        co_return asio::error::eof;
      }
      if (opcode == kPing) {
        // RFC 6455 5.5.2: a Pong with the Ping's data, as soon as the writer lets it in.
        co_await lock_writes();
        std::array<uint8_t, 10> pong{};
        const size_t n = websocket_frame_header(kPong, size, pong);
        const std::array<asio::const_buffer, 2> out{asio::buffer(pong.data(), n), asio::buffer(body, size_t(size))};
        auto [ec, written] = co_await asio::async_write(stream_, out, no_throw);
        unlock_writes();
        if (ec) co_return ec;
        continue;
      }
      if (opcode != kPong) throw protocol::ProtocolError("unknown WebSocket control frame");
      continue;
    }
    if (opcode == kText) throw protocol::ProtocolError("a text WebSocket message: the protocol is binary");
    if (opcode != kBinary && opcode != kContinuation) throw protocol::ProtocolError("unknown WebSocket frame type");
    if ((opcode == kBinary) == in_message) throw protocol::ProtocolError("WebSocket fragments out of order");
    in_message = true;
    // The limit is checked before a byte of the payload is read or room is made for it.
    if (size > kMaxMessage - frame.size()) {
      close_code_ = 1009;
      throw protocol::ProtocolError("WebSocket message over the frame limit");
    }
    const size_t at = frame.size();
    frame.resize(at + size_t(size));
    if (auto ec = co_await read_exactly(frame.data() + at, size_t(size))) co_return ec;
    for (size_t i = 0; i < size; ++i) frame[at + i] ^= mask[i % 4];
    if (fin) break;
  }
  // Exactly one protocol frame per message.
  if (frame.size() < protocol::kHeaderBytes) throw protocol::ProtocolError("WebSocket message shorter than a frame header");
  const protocol::FrameHeader header = protocol::parse_header(frame.data());
  if (frame.size() != protocol::kHeaderBytes + header.length)
    throw protocol::ProtocolError("WebSocket message is not exactly one protocol frame");
  co_return std::error_code();
}

asio::awaitable<void> WebSocketTransport::lock_writes() {
  // The timer never expires: cancel() wakes its waiters, who look again.
  while (writing_) co_await write_free_.async_wait(no_throw);
  writing_ = true;
}

void WebSocketTransport::unlock_writes() {
  writing_ = false;
  write_free_.cancel();
}

asio::awaitable<void> WebSocketTransport::send_close(uint16_t code, const std::string& reason) {
  if (close_sent_) co_return;
  close_sent_ = true;
  uint8_t body[125];
  size_t size = 0;
  if (code != 0) {
    body[0] = uint8_t(code >> 8), body[1] = uint8_t(code);
    const std::string text = reason.substr(0, 123);
    std::memcpy(body + 2, text.data(), text.size());
    size = 2 + text.size();
  }
  co_await lock_writes();
  std::array<uint8_t, 10> head{};
  const size_t n = websocket_frame_header(kClose, size, head);
  const std::array<asio::const_buffer, 2> out{asio::buffer(head.data(), n), asio::buffer(body, size)};
  co_await asio::async_write(stream_, out, no_throw);
  unlock_writes();
}

asio::awaitable<void> WebSocketTransport::goodbye(protocol::ErrorCode error, const std::string& reason) {
  using protocol::ErrorCode;
  uint16_t code = close_code_;
  if (code == 0) code = error == ErrorCode::ShuttingDown ? 1001 : error == ErrorCode::Malformed || error == ErrorCode::BadVersion ? 1002 : 1008;
  co_await send_close(code, reason);
}

asio::awaitable<std::error_code> WebSocketTransport::write_frames(const std::deque<Outgoing>& frames) {
  co_await lock_writes();
  struct Unlock {
    WebSocketTransport* self;
    ~Unlock() { self->unlock_writes(); }
  } unlock{this};
  if (close_sent_) co_return asio::error::eof;  // nothing may follow a Close
  headers_.resize(frames.size());
  buffers_.clear();
  for (size_t i = 0; i < frames.size(); ++i) {
    const size_t n = websocket_frame_header(kBinary, frames[i].frame->size(), headers_[i]);
    buffers_.push_back(asio::buffer(headers_[i].data(), n));
    buffers_.push_back(asio::buffer(*frames[i].frame));
  }
  auto [ec, n] = co_await asio::async_write(stream_, buffers_, no_throw);
  co_return ec;
}


}  // namespace inkwire::server
