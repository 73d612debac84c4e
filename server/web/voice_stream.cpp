#include "server/web/voice_stream.hpp"

#include <cstdio>

#include <asio/experimental/as_tuple.hpp>

namespace inkwire::server {
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

}  // namespace

VoiceStream::VoiceStream(ByteStream stream, std::chrono::steady_clock::duration stuck)
    : stream_(std::move(stream)), stuck_(stuck), wake_(stream_.get_executor(), asio::steady_timer::time_point::max()) {
  // Frames of tens of bytes: under Nagle's rule a frame written while the one before is not yet
  // acknowledged waits for the page's delayed acknowledgement (40 ms and more), which the jitter
  // rule then takes as network delay and adds to every member's mouth to ear.
  std::error_code ec;
  stream_.socket().set_option(asio::ip::tcp::no_delay(true), ec);
}

void VoiceStream::start(std::string head) {
  auto self = shared_from_this();
  asio::co_spawn(stream_.get_executor(), [self, head = std::move(head)]() mutable { return self->write_loop(std::move(head)); }, asio::detached);
  asio::co_spawn(stream_.get_executor(), [self] { return self->watch_peer(); }, asio::detached);
}

void VoiceStream::send(std::shared_ptr<const protocol::Bytes> frame) {
  if (!open_) return;
  if (writing_since_ && std::chrono::steady_clock::now() - *writing_since_ > stuck_) {
    close();  // the page stopped reading: its voice goes back to its connection
    return;
  }
  if (waiting_.size() >= kMaxWaiting) waiting_.pop_front();
  waiting_.push_back(std::move(frame));
  wake_.cancel();
}

void VoiceStream::close() {
  if (!open_) return;
  open_ = false;
  waiting_.clear();
  stream_.close();
  wake_.cancel();
}

asio::awaitable<void> VoiceStream::write_loop(std::string head) {
  auto self = shared_from_this();
  writing_since_ = std::chrono::steady_clock::now();
  auto [ec, n] = co_await asio::async_write(stream_, asio::buffer(head), no_throw);
  writing_since_.reset();
  std::string chunk;
  while (!ec && open_) {
    if (waiting_.empty()) {
      wake_.expires_at(asio::steady_timer::time_point::max());
      co_await wake_.async_wait(no_throw);
      continue;
    }
    // One chunk a frame: its size in hex, the frame, CRLF.
    const auto frame = std::move(waiting_.front());
    waiting_.pop_front();
    char size[16];
    const int digits = std::snprintf(size, sizeof size, "%zx\r\n", frame->size());
    chunk.assign(size, size_t(digits));
    chunk.append(reinterpret_cast<const char*>(frame->data()), frame->size());
    chunk.append("\r\n");
    writing_since_ = std::chrono::steady_clock::now();
    std::tie(ec, n) = co_await asio::async_write(stream_, asio::buffer(chunk), no_throw);
    writing_since_.reset();
  }
  close();
}

asio::awaitable<void> VoiceStream::watch_peer() {
  auto self = shared_from_this();
  // The page sends nothing after its request: whatever comes, or the end, closes the stream.
  char byte;
  co_await stream_.async_read_some(asio::buffer(&byte, 1), no_throw);
  close();
}

}  // namespace inkwire::server
