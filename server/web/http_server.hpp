#pragma once
// The server's HTTP listener (`--http HOST:PORT`, SPEC W1): the WebSocket upgrade at /ws that
// carries protocol frames into the same connections as TCP, /healthz, Prometheus text at
// /metrics, an index of the sessions at /, the pages of sessions, and every product as a static
// host serves its export at /products/NAME/ (protocol/PRODUCT.md). One request per connection; a request head must
// arrive whole within the head timeout and 8 KiB, so a slow or endless client is cut off while
// everyone else is served. WebSockets are refused (403) to pages of origins not allowed: by
// default the server's own pages only.
#include <memory>
#include <string>
#include <vector>

#include <asio.hpp>

#include "protocol/net/byte_stream.hpp"

namespace inkwire::server {

class Server;
struct Request;

class HttpServer {
 public:
  // Binds the listener; throws inkwire::Error if it cannot.
  HttpServer(asio::io_context& io, Server& server);
  uint16_t port() const { return acceptor_.local_endpoint().port(); }
  void start();
  void stop();

 private:
  asio::awaitable<void> serve(ByteStream stream);
  // The long-lived streams a request may become; each sets `handed_over` once the socket is
  // theirs, or gives the reply refusing it.
  asio::awaitable<std::string> upgrade_websocket(ByteStream& socket, const Request& request, std::string early_bytes, bool& handed_over);
  asio::awaitable<std::string> open_voice_stream(ByteStream& socket, const Request& request, const std::string& ticket, bool& handed_over);
  // Every other route: one reply.
  std::string answer(const Request& request, const std::string& path);

  asio::io_context& io_;
  Server& server_;
  asio::ip::tcp::acceptor acceptor_;
  bool stopping_ = false;
};

// Whether a page of `origin` may open a WebSocket to a server reached as `host` (the Host
// header): the server's own ("http://" + host), or an allowed origin (any, when "*" is allowed).
// A request without an Origin (not from a page) is allowed.
bool origin_allowed(const std::string& origin, const std::string& host, const std::vector<std::string>& allowed);

}  // namespace inkwire::server
