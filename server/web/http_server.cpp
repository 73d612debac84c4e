#include "server/web/http_server.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string_view>

#include <asio/experimental/as_tuple.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "server/relay/relay.hpp"
#include "server/connection.hpp"
#include "server/server.hpp"
#include "server/products/product_listing.hpp"
#include "server/web/http_request.hpp"
#include "server/web/metrics.hpp"
#include "server/web/voice_stream.hpp"
#include "server/web/web_files.hpp"
#include "server/web/websocket.hpp"


namespace inkwire::server {
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
constexpr size_t kMaxHead = 8192;

// `headers`: more header lines, each ending in CRLF.
std::string response(int status, const char* reason, const std::string& type, const std::string& body, const std::string& headers = "") {
  return "HTTP/1.1 " + std::to_string(status) + " " + reason + "\r\nContent-Type: " + type + "\r\nContent-Length: " +
         std::to_string(body.size()) + "\r\nCache-Control: no-store\r\nConnection: close\r\n" + headers + "\r\n" + body;
}

// A call's page is cross-origin isolated, so its worker and audio worklets can share rings of
// sound (SharedArrayBuffer) instead of messages that some engines route past the page's thread
// (SPEC F15). The scripts say they may be embedded so, by any page (a worker's own script must
// carry COEP itself, in Chromium).
const std::string kIsolatedPage = "Cross-Origin-Opener-Policy: same-origin\r\nCross-Origin-Embedder-Policy: require-corp\r\n";
// A product's files may be read by pages of any origin (a shop's page, the server's products).
const std::string kAnyOrigin = "Access-Control-Allow-Origin: *\r\n";
const std::string kEmbeddableScript = "Cross-Origin-Embedder-Policy: require-corp\r\nCross-Origin-Resource-Policy: cross-origin\r\n";

// The browser's renderer (client/web/module), which the build leaves beside this binary in web/,
// read once, plain and gzipped. Null when this build has none.
struct ModuleFile {
  std::string plain, gzipped;
};
const ModuleFile* module_file(const std::string& name) {
  static std::mutex guard;
  static std::map<std::string, std::optional<ModuleFile>> cache;
  if (name != "inkwire-scene.js" && name != "inkwire-scene.wasm") return nullptr;
  const std::lock_guard lock(guard);
  auto [it, fresh] = cache.try_emplace(name);
  if (fresh) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "web";
    const auto read = [](const std::filesystem::path& file) {
      std::ifstream in(file, std::ios::binary);
      return in ? std::optional<std::string>(std::string(std::istreambuf_iterator<char>(in), {})) : std::nullopt;
    };
    const std::optional<std::string> plain = read(dir / name), gzipped = read(dir / (name + ".gz"));
    if (plain && gzipped) it->second = ModuleFile{*plain, *gzipped};
  }
  return it->second ? &*it->second : nullptr;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

std::string content_type(const std::string& path) {
  if (path.ends_with(".js")) return "text/javascript; charset=utf-8";
  if (path.ends_with(".wasm")) return "application/wasm";
  if (path.ends_with(".json")) return "application/json";
  return "text/plain; charset=utf-8";  // shaders
}

// Presenter mode from a product page's address (/turntable/NAME?present or ?follow): that
// attribute on the page's element. Anything else in the query is left out.
std::string presenter_attribute(const std::string& target) {
  const size_t query = target.find('?');
  if (query == std::string::npos) return "";
  std::istringstream parts(target.substr(query + 1));
  for (std::string part; std::getline(parts, part, '&');)
    if (part == "present" || part == "follow") return " " + part;
  return "";
}

// A session's page: `element` full-size (with `attributes`), and the snippet to paste into one's
// own page. Over TLS the snippet names https:// and wss:// (a shop's https page may load nothing
// else).
std::string element_page(const std::string& element, const std::string& session, const std::string& host, const std::string& invitation, bool tls,
                         const std::string& attributes = "") {
  const std::string http = tls ? "https://" : "http://", ws = tls ? "wss://" : "ws://";
  const std::string snippet = "<script type=\"module\" src=\"" + http + host + "/inkwire.js\"></script>\n<" + element + " server=\"" + ws +
                              host + "/ws\" session=\"" + session + "\" style=\"width: 480px; height: 480px\"></" + element + ">";
  return "<!doctype html><html lang=en><meta charset=utf-8><meta name=viewport content=\"width=device-width, initial-scale=1\">"
         "<title>" + html_escape(session) + "</title><style>html, body { margin: 0; height: 100%; font: 14px system-ui, sans-serif; }"
         " " + element + " { height: calc(100% - 9em); } details { padding: 0.5em 1em; } pre { white-space: pre-wrap; background: #f4f4f4; padding: 0.5em; }"
         "</style><script type=module src=\"/inkwire.js\"></script><" + element + " session=\"" + html_escape(session) + "\"" + attributes + "></" + element +
         "><details><summary>" + invitation + "</summary><pre>" + html_escape(snippet) + "</pre></details>\n";
}

}  // namespace

bool origin_allowed(const std::string& origin, const std::string& host, const std::vector<std::string>& allowed) {
  if (origin.empty()) return true;
  if (allowed.empty()) return lower(origin) == "http://" + lower(host) || lower(origin) == "https://" + lower(host);
  return std::find(allowed.begin(), allowed.end(), origin) != allowed.end();
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
    co_await reply(response(503, "Service Unavailable", "text/plain", place.refusal() + "\n"));
    co_return;
  }
  // One deadline for the whole exchange (STYLE 16), head and reply, or the connection is cut: a
  // slow-loris client that sends its head a byte at a time, or a reader that never reads its
  // reply, holds one socket for a few seconds at most. A WebSocket hands the socket over once
  // upgraded, with deadlines of its own. Shared with the watchdog, which may run after this
  // coroutine has ended.
  auto handed_over = std::make_shared<bool>(false);
  auto watchdog = std::make_shared<asio::steady_timer>(io_, std::chrono::milliseconds(int64_t(server_.config().http_head_timeout_seconds * 1000)));
  watchdog->async_wait([socket_ptr, handed_over, peer](std::error_code ec) {
    if (ec || *handed_over || !socket_ptr->socket().is_open()) return;
    log_warn("http-too-slow", {{"peer", peer}});
    socket_ptr->close();
  });
  struct CancelAtEnd {
    std::shared_ptr<asio::steady_timer> timer;
    ~CancelAtEnd() { timer->cancel(); }
  } cancel_at_end{watchdog};
  std::string buffer;
  auto [ec, n] = co_await asio::async_read_until(socket, asio::dynamic_buffer(buffer, kMaxHead), "\r\n\r\n", no_throw);
  if (ec) {
    if (ec == asio::error::not_found) co_await reply(response(431, "Request Header Fields Too Large", "text/plain", "request head over 8 KiB\n"));
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
    co_await reply(response(400, "Bad Request", "text/plain", malformed + "\n"));
    co_return;
  }
  if (request.method != "GET") {
    co_await reply(response(405, "Method Not Allowed", "text/plain", "only GET\n"));
    co_return;
  }
  const std::string path = request.path.substr(0, request.path.find('?'));
  if (path == "/ws") {
    const std::string key = request.header("sec-websocket-key");
    if (lower(request.header("upgrade")) != "websocket" || lower(request.header("connection")).find("upgrade") == std::string::npos ||
        request.header("sec-websocket-version") != "13" || key.empty()) {
      co_await reply(response(400, "Bad Request", "text/plain", "a WebSocket (version 13) upgrade is expected here\n"));
      co_return;
    }
    const std::string origin = request.header("origin");
    if (!origin_allowed(origin, request.header("host"), server_.config().allowed_origins)) {
      log_warn("websocket-origin-refused", {{"peer", peer}, {"origin", origin}});
      co_await reply(response(403, "Forbidden", "text/plain", "pages of " + origin + " may not connect\n"));
      co_return;
    }
    const std::string upgrade = "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: " +
                                websocket_accept(key) + "\r\n\r\n";
    auto [wec, wn] = co_await asio::async_write(socket, asio::buffer(upgrade), no_throw);
    if (wec) co_return;
    *handed_over = true;
    place.release();
    server_.adopt(std::make_unique<WebSocketTransport>(std::move(socket), buffer.substr(n)));
    co_return;
  }
  if (path.rfind("/voice/", 0) == 0) {
    // A call member's voice route (protocol/SPEC.md "Voice route"): the socket becomes its stream.
    const std::string origin = request.header("origin");
    if (!origin_allowed(origin, request.header("host"), server_.config().allowed_origins)) {
      co_await reply(response(403, "Forbidden", "text/plain", "pages of " + origin + " may not hear this server's calls\n"));
      co_return;
    }
    const std::shared_ptr<Connection> member = server_.voice_ticket_holder(path.substr(7));
    if (!member) {
      co_await reply(response(404, "Not Found", "text/plain", "no call member has this voice ticket (used, or the member left)\n"));
      co_return;
    }
    const auto stream = std::make_shared<VoiceStream>(std::move(socket), std::chrono::milliseconds(int64_t(server_.config().idle_timeout_seconds * 1000)));
    member->take_voice_stream(stream);
    *handed_over = true;
    place.release();
    std::string head = "HTTP/1.1 200 OK\r\nContent-Type: application/vnd.inkwire.frames\r\nCache-Control: no-store\r\nTransfer-Encoding: chunked\r\n";
    if (!origin.empty()) head += "Access-Control-Allow-Origin: " + origin + "\r\nVary: Origin\r\n";
    if (https) head += "Strict-Transport-Security: max-age=63072000\r\n";
    stream->start(head + "\r\n");
    co_return;
  }
  if (path == "/healthz") {
    // Without its broker an instance still serves its own members: healthy, and it says so.
    const RelayStatus relay = server_.relay().status();
    const std::string body = server_.stopping() ? "stopping\n" : relay.connected ? "ok\n" : "ok, broker away: serving this instance's members only\n";
    co_await reply(response(server_.stopping() ? 503 : 200, server_.stopping() ? "Service Unavailable" : "OK", "text/plain", body));
    co_return;
  }
  if (path == "/metrics") {
    co_await reply(response(200, "OK", "text/plain; version=0.0.4", metrics_text(server_)));
    co_return;
  }
  for (const auto* files : {&web_client_files(), &web_shader_files()})
    if (const auto file = files->find(path.substr(1)); path.size() > 1 && file != files->end()) {
      co_await reply(response(200, "OK", content_type(path), std::string(file->second), kEmbeddableScript));
      co_return;
    }
  if (path.rfind("/module/", 0) == 0) {
    const ModuleFile* file = module_file(path.substr(8));
    if (!file) {
      co_await reply(response(404, "Not Found", "text/plain", "no module file " + path.substr(8) + " (this server was built without the browser's renderer)\n"));
      co_return;
    }
    // Sent compressed to browsers that take it (every one does): the size a page really loads.
    const bool gzip = request.header("accept-encoding").find("gzip") != std::string::npos;
    const std::string& body = gzip ? file->gzipped : file->plain;
    co_await reply("HTTP/1.1 200 OK\r\nContent-Type: " + content_type(path) + (gzip ? "\r\nContent-Encoding: gzip" : "") +
                   "\r\nContent-Length: " + std::to_string(body.size()) + "\r\nCache-Control: no-cache\r\nConnection: close\r\n" + kEmbeddableScript +
                   "\r\n" + body);
    co_return;
  }
  if (path.rfind("/products/", 0) == 0) {
    co_await reply(product_reply(request, path));
    co_return;
  }
  if (path.rfind("/scene/", 0) == 0) {
    const auto session = server_.find_session(path.substr(7));
    if (!session || session->state().kind != protocol::SessionKind::Scene || !session->state().product.directions.empty()) {
      co_await reply(response(404, "Not Found", "text/plain", "no scene " + path.substr(7) + "\n"));
      co_return;
    }
    co_await reply(response(200, "OK", "text/html; charset=utf-8",
                            element_page("inkwire-scene", session->name(), request.header("host"), "Put this scene on your page", server_.tls() != nullptr)));
    co_return;
  }
  if (path.rfind("/turntable/", 0) == 0) {
    const auto session = server_.find_session(path.substr(11));
    if (!session || session->state().product.directions.empty()) {
      co_await reply(response(404, "Not Found", "text/plain", "no product " + path.substr(11) + "\n"));
      co_return;
    }
    co_await reply(response(200, "OK", "text/html; charset=utf-8",
                            element_page("inkwire-turntable", session->name(), request.header("host"), "Put this product on your page", server_.tls() != nullptr,
                                         presenter_attribute(request.path))));
    co_return;
  }
  if (path.rfind("/conference/", 0) == 0) {
    const auto session = server_.find_session(path.substr(12));
    if (!session || session->state().kind != protocol::SessionKind::Conference) {
      co_await reply(response(404, "Not Found", "text/plain", "no conference " + path.substr(12) + "\n"));
      co_return;
    }
    co_await reply(response(200, "OK", "text/html; charset=utf-8",
                            element_page("inkwire-conference", session->name(), request.header("host"), "Put this conference on your page", server_.tls() != nullptr)));
    co_return;
  }
  if (path.rfind("/call/", 0) == 0) {
    // The join link of a call: any conference session.
    const auto session = server_.find_session(path.substr(6));
    if (!session || !session->call()) {
      co_await reply(response(404, "Not Found", "text/plain", "no call " + path.substr(6) + "\n"));
      co_return;
    }
    co_await reply(response(200, "OK", "text/html; charset=utf-8",
                            element_page("inkwire-call", session->name(), request.header("host"), "Put this call on your page", server_.tls() != nullptr),
                            kIsolatedPage));
    co_return;
  }
  if (path == "/") {
    std::string body = "<!doctype html><meta charset=utf-8><title>" + html_escape(server_.config().name) + "</title><h1>" +
                       html_escape(server_.config().name) + "</h1><ul>";
    for (const auto& [name, session] : server_.sessions()) {
      const bool product = !session->state().product.directions.empty();
      const bool conference = session->state().kind == protocol::SessionKind::Conference;
      const std::string link = product ? "/turntable/" : conference ? "/conference/" : "/scene/";
      body += "<li>" + (!link.empty() ? "<a href=\"" + link + html_escape(name) + "\">" + html_escape(name) + "</a>" : html_escape(name)) +
              (conference ? " (<a href=\"/call/" + html_escape(name) + "\">join the call</a>)" : "") +
              " (" + protocol::to_string(session->state().kind) + ", " + std::to_string(session->members()) + " members)</li>";
    }
    co_await reply(response(200, "OK", "text/html; charset=utf-8", body + "</ul>\n"));
    co_return;
  }
  co_await reply(response(404, "Not Found", "text/plain", "no page " + path + "\n"));
}

// A product's files as a static host serves its export (protocol/PRODUCT.md, deploy/nginx/): the
// manifest revalidated each visit (an ETag answers a repeat visit with 304), the files under
// their hashes kept forever, every reply readable by pages of any origin. The manifest of a
// product with a token is given for the token only (?token=); its files are named by hashes
// nobody can guess without it.
std::string HttpServer::product_reply(const Request& request, const std::string& path) {
  const std::string rest = path.substr(std::string("/products/").size());
  const size_t slash = rest.find('/');
  const auto session = slash == std::string::npos ? nullptr : server_.find_session(rest.substr(0, slash));
  if (!session || session->state().product.directions.empty())
    return response(404, "Not Found", "text/plain", "no product " + rest.substr(0, slash) + "\n", kAnyOrigin);
  const std::shared_ptr<const ProductListing> listing = session->listing();
  if (!listing) return response(503, "Service Unavailable", "text/plain", session->unavailable() + "\n", kAnyOrigin);
  const std::string file = rest.substr(slash + 1);
  const auto served = [&](const std::string& type, const std::string& cache, const std::string& body, const std::string& headers = "") {
    return "HTTP/1.1 200 OK\r\nContent-Type: " + type + "\r\nContent-Length: " + std::to_string(body.size()) + "\r\nCache-Control: " + cache +
           "\r\nConnection: close\r\n" + kAnyOrigin + headers + "\r\n" + body;
  };
  if (file == "product.json") {
    if (!session->role_of(query_value(request.path, "token")))
      return response(403, "Forbidden", "text/plain", "product " + session->name() + " needs its token (?token=)\n", kAnyOrigin);
    const std::string& tag = listing->etag;
    if (request.header("if-none-match") == tag)
      return "HTTP/1.1 304 Not Modified\r\nETag: " + tag + "\r\nCache-Control: no-cache\r\nConnection: close\r\n" + kAnyOrigin + "\r\n";
    if (request.header("accept-encoding").find("gzip") == std::string::npos)
      return served("application/json", "no-cache", listing->manifest, "ETag: " + tag + "\r\n");
    return served("application/json", "no-cache", listing->manifest_gzipped, "ETag: " + tag + "\r\nContent-Encoding: gzip\r\nVary: Accept-Encoding\r\n");
  }
  const auto found = listing->files.find(file);
  if (found == listing->files.end()) return response(404, "Not Found", "text/plain", "product " + session->name() + " has no file " + file + "\n", kAnyOrigin);
  const ProductFile& f = found->second;
  const protocol::Bytes bytes = f.cell ? *f.cell : server_.store().read(f.hash, 0, uint32_t(f.size));
  return served(f.content_type, "public, max-age=31536000, immutable", std::string(bytes.begin(), bytes.end()));
}

}  // namespace inkwire::server
