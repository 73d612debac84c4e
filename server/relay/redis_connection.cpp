#include "server/relay/redis_connection.hpp"

#include <hiredis/async.h>
#include <hiredis/hiredis.h>

#include "common/log.hpp"

namespace inkwire::server {

// hiredis' event hooks on an Asio descriptor. hiredis owns the socket and frees the context
// (calling `cleanup`) when the connection ends; handlers still waiting hold this by a shared
// pointer and see `dead`, so nothing touches a freed context.
struct RedisConnection::Watch : std::enable_shared_from_this<Watch> {
  Watch(asio::io_context& io, redisAsyncContext* context) : fd(io), ac(context) { fd.assign(ac->c.fd); }

  asio::posix::stream_descriptor fd;
  redisAsyncContext* ac;
  bool want_read = false, want_write = false, read_armed = false, write_armed = false, dead = false;

  void arm_read() {
    if (read_armed || dead) return;
    read_armed = true;
    fd.async_wait(asio::posix::stream_descriptor::wait_read, [self = shared_from_this()](std::error_code ec) {
      self->read_armed = false;
      if (ec || self->dead || !self->want_read) return;
      redisAsyncHandleRead(self->ac);
      if (!self->dead && self->want_read) self->arm_read();
    });
  }
  void arm_write() {
    if (write_armed || dead) return;
    write_armed = true;
    fd.async_wait(asio::posix::stream_descriptor::wait_write, [self = shared_from_this()](std::error_code ec) {
      self->write_armed = false;
      if (ec || self->dead || !self->want_write) return;
      redisAsyncHandleWrite(self->ac);
      if (!self->dead && self->want_write) self->arm_write();
    });
  }
  // hiredis closes the socket itself right after: let go of it without closing.
  void cleanup() {
    dead = true;
    std::error_code ec;
    fd.cancel(ec);
    fd.release();
  }

  static Watch& of(void* privdata) { return *static_cast<Watch*>(privdata); }
  static void add_read(void* p) { of(p).want_read = true, of(p).arm_read(); }
  static void del_read(void* p) { of(p).want_read = false; }
  static void add_write(void* p) { of(p).want_write = true, of(p).arm_write(); }
  static void del_write(void* p) { of(p).want_write = false; }
  static void clean_up(void* p) { of(p).cleanup(); }
};

namespace {

// Handlers must not throw through hiredis' C frames.
void run(const RedisConnection::ReplyHandler& handler, const redisReply* reply) {
  try {
    handler(reply);
  } catch (const std::exception& e) {
    log(LogLevel::Error, "broker-handler-failed", {{"reason", e.what()}});
  }
}

void reply_once(redisAsyncContext*, void* reply, void* privdata) {
  const std::unique_ptr<RedisConnection::ReplyHandler> handler(static_cast<RedisConnection::ReplyHandler*>(privdata));
  run(*handler, static_cast<const redisReply*>(reply));
}

void reply_each(redisAsyncContext*, void* reply, void* privdata) {
  run(*static_cast<RedisConnection::ReplyHandler*>(privdata), static_cast<const redisReply*>(reply));
}

bool send_argv(redisAsyncContext* ac, redisCallbackFn* callback, void* privdata, const std::vector<std::string_view>& args) {
  std::vector<const char*> argv;
  std::vector<size_t> lengths;
  for (const std::string_view a : args) argv.push_back(a.data()), lengths.push_back(a.size());
  return redisAsyncCommandArgv(ac, callback, privdata, int(argv.size()), argv.data(), lengths.data()) == REDIS_OK;
}

}  // namespace

RedisConnection::RedisConnection(asio::io_context& io) : io_(io), connect_timer_(io) {}

RedisConnection::~RedisConnection() { disconnect(); }

void RedisConnection::connect(const std::string& host, uint16_t port, std::chrono::milliseconds timeout, std::function<void()> up,
                              std::function<void(const std::string&)> down) {
  disconnect();
  up_ = std::move(up);
  down_ = std::move(down);
  redisAsyncContext* ac = redisAsyncConnect(host.c_str(), port);
  if (!ac || ac->err) {
    const std::string reason = ac ? ac->errstr : "out of memory";
    if (ac) redisAsyncFree(ac);
    // Reported from the loop, as a failure found later would be.
    asio::post(io_, [this, reason] { went_down(reason); });
    return;
  }
  ac_ = ac;
  ac->data = this;
  watch_ = std::make_shared<Watch>(io_, ac);
  ac->ev.data = watch_.get();
  ac->ev.addRead = Watch::add_read;
  ac->ev.delRead = Watch::del_read;
  ac->ev.addWrite = Watch::add_write;
  ac->ev.delWrite = Watch::del_write;
  ac->ev.cleanup = Watch::clean_up;
  redisAsyncSetConnectCallback(ac, on_connect);
  redisAsyncSetDisconnectCallback(ac, on_disconnect);
  Watch::add_write(watch_.get());  // a non-blocking connect completes when the socket is writable
  connect_timer_.expires_after(timeout);
  connect_timer_.async_wait([this](std::error_code ec) {
    if (ec || connected_ || !ac_) return;
    disconnect_keeping_handlers();
    went_down("no answer within the connect timeout");
  });
}

void RedisConnection::on_connect(const redisAsyncContext* ac, int status) {
  auto* self = static_cast<RedisConnection*>(ac->data);
  if (!self) return;
  self->connect_timer_.cancel();
  if (status != REDIS_OK) {
    self->ac_ = nullptr;  // hiredis frees it after this call
    self->went_down(ac->errstr);
    return;
  }
  self->connected_ = true;
  if (auto up = std::exchange(self->up_, nullptr)) up();
}

void RedisConnection::on_disconnect(const redisAsyncContext* ac, int status) {
  auto* self = static_cast<RedisConnection*>(ac->data);
  if (!self) return;
  self->ac_ = nullptr;  // hiredis frees it after this call
  self->connected_ = false;
  self->went_down(status == REDIS_OK ? "closed" : ac->errstr);
}

void RedisConnection::went_down(const std::string& reason) {
  connected_ = false;
  up_ = nullptr;
  if (auto down = std::exchange(down_, nullptr)) down(reason);
}

bool RedisConnection::command(const std::vector<std::string_view>& args, ReplyHandler done) {
  if (!ac_ || !connected_) return false;
  auto* handler = new ReplyHandler(std::move(done));
  if (!send_argv(ac_, reply_once, handler, args)) {
    delete handler;
    return false;
  }
  return true;
}

bool RedisConnection::subscribe(const std::vector<std::string_view>& channels, ReplyHandler each) {
  if (!ac_ || !connected_) return false;
  subscriber_ = std::make_unique<ReplyHandler>(std::move(each));
  std::vector<std::string_view> args{"SUBSCRIBE"};
  args.insert(args.end(), channels.begin(), channels.end());
  return send_argv(ac_, reply_each, subscriber_.get(), args);
}

void RedisConnection::disconnect_keeping_handlers() {
  connect_timer_.cancel();
  connected_ = false;
  if (redisAsyncContext* ac = std::exchange(ac_, nullptr)) {
    ac->data = nullptr;  // no connect or disconnect callback into this object any more
    redisAsyncFree(ac);  // pending reply handlers run with null; `cleanup` lets go of the socket
  }
}

void RedisConnection::disconnect() {
  up_ = nullptr;
  down_ = nullptr;
  disconnect_keeping_handlers();
}

}  // namespace inkwire::server
