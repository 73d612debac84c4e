#pragma once
// One connection to a Redis server through hiredis' asynchronous API, driven by the server's
// Asio I/O thread: hiredis says when it wants to read or write, Asio waits on the socket and
// calls back into hiredis. Nothing here blocks: connecting, commands and replies all complete
// through callbacks on the I/O thread. Not thread-safe (one I/O thread, as the server).
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <asio.hpp>

struct redisAsyncContext;
struct redisReply;

namespace inkwire::server {

class RedisConnection {
 public:
  // A reply, or null when the connection went away before it came.
  using ReplyHandler = std::function<void(const redisReply*)>;

  explicit RedisConnection(asio::io_context& io);
  ~RedisConnection();  // disconnects; pending handlers are called with null
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  // Starts connecting. Exactly one of `up` (connected) and `down` (could not connect, or the
  // connection was lost later, with the reason) follows per connect(), `down` at most once.
  void connect(const std::string& host, uint16_t port, std::chrono::milliseconds timeout, std::function<void()> up,
               std::function<void(const std::string&)> down);
  bool connected() const { return connected_; }
  // Sends a command (arguments may hold any bytes). False, and `done` never called, when not
  // connected.
  bool command(const std::vector<std::string_view>& args, ReplyHandler done);
  // SUBSCRIBE: `each` sees the confirmation and then every message, until the connection ends
  // (then null once).
  bool subscribe(const std::vector<std::string_view>& channels, ReplyHandler each);
  // Drops the connection now (pending handlers see null; `down` is not called).
  void disconnect();

 private:
  struct Watch;
  static void on_connect(const redisAsyncContext* ac, int status);
  static void on_disconnect(const redisAsyncContext* ac, int status);
  void went_down(const std::string& reason);
  void disconnect_keeping_handlers();

  asio::io_context& io_;
  redisAsyncContext* ac_ = nullptr;
  std::shared_ptr<Watch> watch_;
  asio::steady_timer connect_timer_;
  std::function<void()> up_;
  std::function<void(const std::string&)> down_;
  std::unique_ptr<ReplyHandler> subscriber_;  // lives as long as the subscription
  bool connected_ = false;
};

}  // namespace inkwire::server
