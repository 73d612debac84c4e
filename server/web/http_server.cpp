#include "server/web/http_server.hpp"

#include <algorithm>
#include <array>

#include <asio/experimental/as_tuple.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "server/connection.hpp"
#include "server/relay/relay.hpp"
#include "server/server.hpp"
#include "server/web/client_files.hpp"
#include "server/web/http_reply.hpp"
#include "server/web/http_request.hpp"
#include "server/web/metrics.hpp"
#include "server/web/pages.hpp"
#include "server/web/product_files.hpp"
#include "server/web/uploads.hpp"
#include "server/web/voice_stream.hpp"
#include "server/web/websocket.hpp"

namespace inkwire::server {
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
constexpr size_t kMaxHead = 8192;

// What a page of a refused origin is told, readable by it (the element shows it: a refused
// WebSocket itself tells a page nothing).
std::string origin_refusal(const std::string& origin) {
  return text_reply(403, "this server does not accept pages of " + origin, kAnyOrigin);
}

}  // namespace

bool origin_allowed(const std::string& origin, const std::string& host, const std::vector<std::string>& allowed) {
  // The server's own pages always may, whatever else is allowed.
  if (origin.empty() || lower(origin) == "http://" + lower(host) || lower(origin) == "https://" + lower(host)) return true;
  return std::find(allowed.begin(), allowed.end(), origin) != allowed.end() || std::find(allowed.begin(), allowed.end(), "*") != allowed.end();
}

HttpServer::HttpServer(asio::io_context& io, Server& server) : io_(io), server_(server), acceptor_(io) {
  const ServerConfig& c = server.config();
  std::error_code ec;
  const auto address = asio::ip::make_address(c.http_host == "localhost" ? "127.0.0.1" : c.http_host, ec);
  if (ec) throw Error("http host '" + c.http_host + "' is not an IP address");
  const asio::ip::tcp::endpoint endpoint(address, c.http_port);
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw Error("cannot listen for HTTP on " + c.http_host + ":" + std::to_string(c.http_port) + ": " + ec.message());
}

void HttpServer::start() {
  log_info("http-listening", {{"host", server_.config().http_host}, {"port", port()}});
  // The handshake shares the head's time limit: a peer that says nothing is cut off either way.
  const auto timeout = std::chrono::milliseconds(int64_t(server_.config().http_head_timeout_seconds * 1000));
  asio::co_spawn(io_, accept_connections(acceptor_, stopping_, "http-accept-failed", [this, timeout](asio::ip::tcp::socket socket) {
                   secure_then(std::move(socket), server_.tls(), timeout, [this](ByteStream stream) {
                     asio::co_spawn(io_, serve(std::move(stream)), asio::detached);
                   });
                 }), asio::detached);
}

void HttpServer::stop() {
  stopping_ = true;
  std::error_code ec;
  acceptor_.close(ec);
}

namespace {

// An HTTP request's place among the server's clients (Admission::take_place) while it is read and
// answered; a WebSocket gives it up to become a connection, which takes its own.
class Place {
 public:
  Place(Server& server, std::string address) : server_(server), address_(std::move(address)), refusal_(server.admission().take_place(address_)) {}
  ~Place() { release(); }
  Place(const Place&) = delete;
  Place& operator=(const Place&) = delete;
  const std::string& refusal() const { return refusal_; }
  const std::string& address() const { return address_; }
  void release() {
    if (std::exchange(held_, false)) server_.admission().give_place(address_);
  }

 private:
  Server& server_;
  std::string address_, refusal_;
  bool held_ = true;
};

}  // namespace

asio::awaitable<void> HttpServer::serve(ByteStream accepted) {
  const std::string peer = peer_of(accepted.socket());
  std::error_code address_error;
  Place place(server_, accepted.socket().remote_endpoint(address_error).address().to_string());
  auto socket_ptr = std::make_shared<ByteStream>(std::move(accepted));
  auto& socket = *socket_ptr;
  // Over HTTPS every reply tells the browser to come back over HTTPS only (HSTS, two years).
  const bool https = server_.tls() != nullptr;
  auto reply = [&](std::string text) -> asio::awaitable<void> {
    if (https) text.insert(text.find("\r\n") + 2, "Strict-Transport-Security: max-age=63072000\r\n");
    co_await asio::async_write(socket, asio::buffer(text), no_throw);
    socket.close();
  };
  if (!place.refusal().empty()) {
    co_await reply(text_reply(503, place.refusal()));
    co_return;
  }
  // One deadline for the whole exchange (SPEC D4), head and reply, or the connection is cut: a
  // slow-loris client that sends its head a byte at a time, or a reader that never reads its
  // reply, holds one socket for a few seconds at most. A WebSocket hands the socket over once
  // upgraded, with deadlines of its own. Shared with the watchdog, which may run after this
  // coroutine has ended.
  auto handed_over = std::make_shared<bool>(false);
  const auto timeout = std::chrono::milliseconds(int64_t(server_.config().http_head_timeout_seconds * 1000));
  auto watchdog = std::make_shared<asio::steady_timer>(io_, timeout);
  const auto cut_off_when_late = [socket_ptr, handed_over, peer](std::error_code ec) {
    if (ec || *handed_over || !socket_ptr->socket().is_open()) return;
    log_warn("http-too-slow", {{"peer", peer}});
    socket_ptr->close();
  };
  watchdog->async_wait(cut_off_when_late);
  struct CancelAtEnd {
    std::shared_ptr<asio::steady_timer> timer;
    ~CancelAtEnd() { timer->cancel(); }
  } cancel_at_end{watchdog};
  std::string buffer;
  auto [ec, n] = co_await asio::async_read_until(socket, asio::dynamic_buffer(buffer, kMaxHead), "\r\n\r\n", no_throw);
  if (ec) {
    if (ec == asio::error::not_found) co_await reply(text_reply(431, "request head over 8 KiB"));
    co_return;
  }
  Request request;
  std::string malformed;
  try {
    request = parse_head(buffer.substr(0, n));
  } catch (const Error& e) {
    malformed = e.what();
  }
  if (!malformed.empty()) {
    log_warn("http-malformed", {{"peer", peer}, {"reason", malformed}});
    co_await reply(text_reply(400, malformed));
    co_return;
  }
  const std::string path = request.path.substr(0, request.path.find('?'));
  if (request.method == "POST" && (path == "/scenes" || path.starts_with("/scenes/"))) {
    const std::string origin = request.header("origin");
    if (!origin_allowed(origin, request.header("host"), server_.config().allowed_origins)) {
      co_await reply(origin_refusal(origin));
      co_return;
    }
    // An upload keeps its own deadline (a stall cuts it off); its reply gets the usual one.
    *handed_over = true;
    std::string answer = co_await receive_upload(server_, socket, request, path, buffer.substr(n), place.address());
    *handed_over = false;
    watchdog->expires_after(timeout);
    watchdog->async_wait(cut_off_when_late);
    if (https) answer.insert(answer.find("\r\n") + 2, "Strict-Transport-Security: max-age=63072000\r\n");
    co_await asio::async_write(socket, asio::buffer(answer), no_throw);
    // A refused upload's sender may still be sending: what it sends is read and dropped for a
    // moment after the reply (a close with unread bytes would reset the connection, and the
    // browser would lose the reply).
    std::error_code ignored;
    socket.socket().shutdown(asio::ip::tcp::socket::shutdown_send, ignored);
    watchdog->expires_after(std::chrono::seconds(1));
    watchdog->async_wait(cut_off_when_late);
    for (std::array<char, 16384> drop;;)
      if (auto [ec, dropped] = co_await socket.async_read_some(asio::buffer(drop), no_throw); ec) break;
    socket.close();
    co_return;
  }
  if (request.method != "GET") {
    co_await reply(text_reply(405, request.method == "POST" ? "only GET here (uploads go to POST /scenes)" : "only GET"));
    co_return;
  }
  if (path == "/ws" || path.starts_with("/voice/")) {
    // Both become long-lived streams: pages of origins not allowed are refused first, with a
    // reason the page can read (a plain GET of /ws from the element asks for it).
    const std::string origin = request.header("origin");
    if (!origin_allowed(origin, request.header("host"), server_.config().allowed_origins)) {
      log_warn("websocket-origin-refused", {{"peer", peer}, {"origin", origin}});
      co_await reply(origin_refusal(origin));
      co_return;
    }
    // (Each co_await a statement of its own: GCC 12 miscompiles co_await inside ?:, freeing what it should not.)
    std::string refused;
    if (path == "/ws") refused = co_await upgrade_websocket(socket, request, buffer.substr(n), *handed_over);
    else refused = co_await open_voice_stream(socket, request, path.substr(7), *handed_over);
    if (*handed_over) place.release();
    else if (!refused.empty()) co_await reply(refused);
    co_return;
  }
  co_await reply(answer(request, path));
}

// A WebSocket (RFC 6455) handed to the server as a connection, or the reply refusing it.
asio::awaitable<std::string> HttpServer::upgrade_websocket(ByteStream& socket, const Request& request, std::string early_bytes, bool& handed_over) {
  const std::string key = request.header("sec-websocket-key");
  if (lower(request.header("upgrade")) != "websocket" || lower(request.header("connection")).find("upgrade") == std::string::npos ||
      request.header("sec-websocket-version") != "13" || key.empty())
    co_return text_reply(400, "a WebSocket (version 13) upgrade is expected here", kAnyOrigin);
  const std::string upgrade = "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: " +
                              websocket_accept(key) + "\r\n\r\n";
  auto [ec, written] = co_await asio::async_write(socket, asio::buffer(upgrade), no_throw);
  if (ec) co_return "";
  handed_over = true;
  server_.adopt(std::make_unique<WebSocketTransport>(std::move(socket), std::move(early_bytes)));
  co_return "";
}

// A call member's voice route (protocol/SPEC.md "Voice route"): the socket becomes its stream,
// or the reply refusing it.
asio::awaitable<std::string> HttpServer::open_voice_stream(ByteStream& socket, const Request& request, const std::string& ticket, bool& handed_over) {
  const std::shared_ptr<Connection> member = server_.voice_ticket_holder(ticket);
  if (!member) co_return text_reply(404, "no call member has this voice ticket (used, or the member left)");
  const auto stream = std::make_shared<VoiceStream>(std::move(socket), std::chrono::milliseconds(int64_t(server_.config().idle_timeout_seconds * 1000)));
  member->take_voice_stream(stream);
  handed_over = true;
  const std::string origin = request.header("origin");
  std::string head = "HTTP/1.1 200 OK\r\nContent-Type: application/vnd.inkwire.frames\r\nCache-Control: no-store\r\nTransfer-Encoding: chunked\r\n";
  if (!origin.empty()) head += "Access-Control-Allow-Origin: " + origin + "\r\nVary: Origin\r\n";
  if (server_.tls()) head += "Strict-Transport-Security: max-age=63072000\r\n";
  stream->start(head + "\r\n");
  co_return "";
}

// The routes that answer with one reply, in the order they are tried.
std::string HttpServer::answer(const Request& request, const std::string& path) {
  if (path == "/healthz") {
    // Without its broker an instance still serves its own members: healthy, and it says so.
    if (server_.stopping()) return text_reply(503, "stopping");
    return text_reply(200, server_.relay().status().connected ? "ok" : "ok, broker away: serving this instance's members only");
  }
  if (path == "/metrics") return http_reply(200, "text/plain; version=0.0.4", metrics_text(server_));
  if (path == "/") return front_page(server_);
  if (path.starts_with("/products/")) return product_reply(server_, request, path);
  if (std::optional<std::string> file = client_file_reply(request, path)) return std::move(*file);
  if (std::optional<std::string> page = session_page(server_, request, path)) return std::move(*page);
  return text_reply(404, "no page " + path);
}

}  // namespace inkwire::server
