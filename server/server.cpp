#include "server/server.hpp"

#include <malloc.h>

#include <asio/experimental/as_tuple.hpp>

#include "common/error.hpp"
#include "common/face/landmarks_file.hpp"
#include "common/log.hpp"
#include "server/call/call_analyst.hpp"
#include "server/connection.hpp"
#include "server/making/session_maker.hpp"
#include "server/face/face_feed.hpp"
#include "server/relay/relay.hpp"
#include "server/transport.hpp"
#include "server/web/http_server.hpp"

namespace inkwire::server {
namespace fs = std::filesystem;
namespace {

constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

asio::ip::tcp::endpoint endpoint_of(const ServerConfig& config) {
  std::error_code ec;
  auto address = asio::ip::make_address(config.host == "localhost" ? "127.0.0.1" : config.host, ec);
  if (ec) throw Error("listen host '" + config.host + "' is not an IP address");
  return {address, config.port};
}

bool loopback(const std::string& host) {
  std::error_code ec;
  const auto ip = asio::ip::make_address(host == "localhost" ? "127.0.0.1" : host, ec);
  return !ec && ip.is_loopback();
}

// Plain TCP is for this machine (SPEC D3): a listener others can reach carries TLS, unless the
// config says a TLS proxy in front does it.
void refuse_plain_off_loopback(const ServerConfig& c) {
  if (c.tls || c.plain_off_loopback) return;
  for (const auto& [host, what] : {std::pair{c.host, "listen"}, std::pair{c.http ? c.http_host : std::string("127.0.0.1"), "http"}})
    if (!loopback(host))
      throw Error(std::string(what) + " on " + host + " is reachable from other machines: give \"tls\" (certificate and key) in the config, "
                  "or \"plain_off_loopback\": true when a TLS proxy stands in front");
}

}  // namespace

Server::Server(asio::io_context& io, ServerConfig config) : io_(io), config_(std::move(config)), acceptor_(io), persist_timer_(io) {
  // What can be refused is refused before anything is bound or created on disk.
  if (config_.tls) tls_ = server_tls_context(config_.tls->certificate, config_.tls->key);
  refuse_plain_off_loopback(config_);
  // Ports first: a busy port fails before anything is created on disk.
  const auto endpoint = endpoint_of(config_);
  std::error_code ec;
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(asio::ip::tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw Error("cannot listen on " + config_.host + ":" + std::to_string(config_.port) + ": " + ec.message());
  if (config_.http) http_ = std::make_unique<HttpServer>(io, *this);
  relay_ = make_relay(*this, config_.broker);  // a broker this build cannot use is refused before the data folder is made
  store_.emplace(config_.data_dir);
  registry_.emplace(*store_, config_);
  maker_.emplace(config_.making, !loopback(config_.host) || (config_.http && !loopback(config_.http_host)), *registry_, config_.limit_loopback);
  create_sessions();
}

uint16_t Server::http_port() const { return http_ ? http_->port() : 0; }

Server::~Server() = default;

void Server::create_sessions() {
  registry_->load();
  // Every conference session is a call its members may publish in (those added later too); their
  // pictures are analysed on one thread, whose results come back to this I/O thread.
  call_analyst_ = std::make_unique<CallAnalyst>([this](CallAnalyst::Result result) {
    asio::post(io_, [this, result = std::move(result)] {
      std::visit([&](const auto& r) {
        if (const auto session = find_session(r.who.session); session && session->call()) session->call()->analysed(r);
      }, result);
    });
  });
  registry_->on_added = [this](Session& session) {
    start_call(session);
    relay_->session_added(session);
  };
  registry_->on_removed = [this](Session& session) {
    const char* what = !session.state().product.directions.empty() ? "product " : session.call() ? "room " : "scene ";
    session.close_members(protocol::ErrorCode::NoSession, what + session.name() + " was removed");
    relay_->session_removed(session);
  };
  for (auto& [name, session] : registry_->all()) start_call(*session);
}

void Server::start_call(Session& session) {
  if (session.state().kind == protocol::SessionKind::Conference) session.start_call(config_.call, *call_analyst_, counters_.call, *relay_, config_.name);
}

std::shared_ptr<Session> Server::find_session(const std::string& name) const { return registry_->find(name); }

void Server::deliver(Session& session, const protocol::Message& change, uint64_t sender, std::optional<uint32_t> revision) {
  if (!session.apply(change, sender)) return;
  if (revision) session.set_revision(*revision);
  // Style changes are rare and matter after a restart: persisted at once; poses on a timer.
  if (protocol::type_of(change) == protocol::MessageType::StyleChange) {
    log_info("style", {{"session", session.name()}, {"client", sender}, {"renderer", session.state().style.renderer}});
    persist(session);
  }
}

void Server::start_face_feeds() {
  // A speaker that cannot be set up (no source, no face in the photo) is logged and left out;
  // every other session is served as usual.
  for (const SessionConfig& c : config_.sessions) {
    if (!c.face) continue;
    const std::shared_ptr<Session> session = find_session(c.name);
    try {
      auto feed = std::make_unique<FaceFeed>(*c.face);
      const fs::path dir = config_.data_dir / "faces";
      fs::create_directories(dir);
      const fs::path photo = dir / (c.name + "-neutral.png"), landmarks = dir / (c.name + "-neutral.landmarks.json");
      save_image(feed->neutral(), photo, false);
      save_landmarks(landmarks, feed->landmarks());
      session->set_face_assets(store_->add_file(photo, protocol::AssetKind::Image),
                               store_->add_file(landmarks, protocol::AssetKind::Landmarks));
      persist(*session);
      std::weak_ptr<Session> weak = session;
      feed->start([this, weak](const protocol::ExpressionCode& code) {
        asio::post(io_, [this, weak, code] {
          if (const auto s = weak.lock()) relay_->publish(*s, code, 0);
        });
      });
      log_info("face-source-started", {{"session", c.name}, {"source", c.face->source},
                                       {"photo", {feed->neutral().width, feed->neutral().height}}});
      face_feeds_.push_back(std::move(feed));
    } catch (const std::exception& e) {
      log(LogLevel::Error, "face-source-failed", {{"session", c.name}, {"source", c.face->source}, {"reason", e.what()}});
    }
  }
}

std::map<std::pair<std::string, bool>, size_t> Server::connections_by_kind() const {
  std::map<std::pair<std::string, bool>, size_t> kinds;
  for (const auto& [key, connection] : connections_) ++kinds[{connection->transport().name(), connection->in_session()}];
  return kinds;
}

void Server::start() {
  start_face_feeds();
  log_info("listening", {{"host", config_.host}, {"port", port()}, {"data", config_.data_dir.string()}, {"sessions", registry_->all().size()}});
  const auto handshake = std::chrono::milliseconds(int64_t(config_.hello_timeout_seconds * 1000));
  asio::co_spawn(io_, accept_connections(acceptor_, stopping_, "accept-failed", [this, handshake](asio::ip::tcp::socket socket) {
                   secure_then(std::move(socket), tls_, handshake, [this](ByteStream stream) { adopt(std::make_unique<TcpTransport>(std::move(stream))); });
                 }), asio::detached);
  asio::co_spawn(io_, persist_loop(), asio::detached);
  asio::co_spawn(io_, call_loop(), asio::detached);
  if (http_) http_->start();
  relay_->start();
}

asio::awaitable<void> Server::call_loop() {
  asio::steady_timer timer(io_);
  while (!stopping_) {
    timer.expires_after(std::chrono::milliseconds(200));
    co_await timer.async_wait(no_throw);
    for (auto& [name, session] : registry_->all())
      if (Call* call = session->call()) call->tick();
  }
}

asio::awaitable<void> Server::persist_loop() {
  while (!stopping_) {
    persist_timer_.expires_after(std::chrono::milliseconds(int64_t(config_.persist_seconds * 1000)));
    co_await persist_timer_.async_wait(no_throw);
    for (auto& [name, session] : registry_->all())
      if (session->dirty) registry_->persist(*session);
    registry_->adopt_stored_elsewhere();
    maker_->sweep(SessionMaker::Clock::now());
    // After a burst of connections (an attack, a crowd leaving) glibc keeps the freed memory in
    // its arenas: hand it back, so the server's size follows what it serves (SPEC D6).
    if (connections_.size() < peak_connections_ / 2) {
      malloc_trim(0);
      peak_connections_ = connections_.size();
    }
    peak_connections_ = std::max(peak_connections_, connections_.size());
  }
}


void Server::forget(const Connection* connection) {
  const std::string address = connection->address();  // erasing may end the connection
  if (connections_.erase(connection)) admission_.give_place(address);
}

std::shared_ptr<Connection> Server::voice_ticket_holder(const std::string& ticket) const {
  for (const auto& [key, connection] : connections_)
    if (connection->holds_voice_ticket(ticket)) return connection;
  return nullptr;
}

void Server::adopt(std::unique_ptr<Transport> transport) {
  if (stopping_) {
    transport->close();
    return;
  }
  auto connection = std::make_shared<Connection>(std::move(transport), *this, next_id_++);
  const std::string refusal = admission_.take_place(connection->address());
  connections_[connection.get()] = connection;
  connection->start();
  // Past a cap the newcomer is told why and let go; everyone already connected carries on.
  if (!refusal.empty()) connection->close_with(protocol::ErrorCode::Refused, refusal);
}

void Server::stop() {
  if (stopping_) return;
  stopping_ = true;
  log_info("stopping", {{"clients", connections_.size()}});
  std::error_code ec;
  acceptor_.close(ec);
  if (http_) http_->stop();
  persist_timer_.cancel();
  relay_->stop();
  face_feeds_.clear();  // joins their threads; codes they posted are applied or dropped with the context
  for (auto& [name, session] : registry_->all()) registry_->persist(*session);
  // Copy: closing connections forget themselves.
  auto open = connections_;
  for (auto& [raw, connection] : open) connection->close_with(protocol::ErrorCode::ShuttingDown, "server shutting down");
}

}  // namespace inkwire::server
