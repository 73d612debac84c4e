#pragma once
// The Inkwire server (SPEC N1-N4): accepts clients on one Asio I/O thread, serves its sessions
// (SessionRegistry) and assets from the store, persists session state on a timer, shuts down
// gracefully.
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <asio.hpp>
#include <asio/ssl.hpp>

#include "server/admission.hpp"
#include "server/asset_store.hpp"
#include "server/config.hpp"
#include "server/making/session_maker.hpp"
#include "server/relay/session_fanout.hpp"
#include "server/session.hpp"
#include "server/session_registry.hpp"

namespace inkwire::server {

class CallAnalyst;
class Connection;
class FaceFeed;
class HttpServer;
class Relay;
class Transport;

// What /metrics counts since the start (touched on the I/O thread only).
struct ServerCounters {
  uint64_t messages_in = 0, messages_out = 0;
  uint64_t replaced = 0;             // state messages overtaken in a queue before they went out (latest wins)
  uint64_t too_slow = 0;             // clients closed because their queue overflowed
  uint64_t idle_closed = 0;          // clients closed past their deadline: silent, or not taking writes (SPEC D7)
  uint64_t changes_refused = 0;      // changes a member had no authority to make (authority.hpp)
  Call::Counters call;               // calls' crops analysed and their time, voice relayed, drops by reason
};

class Server final : public SessionFanout {
 public:
  // Opens the store (creating the demo sessions on first start) and binds the listening socket.
  // Throws inkwire::Error if either fails.
  Server(asio::io_context& io, ServerConfig config);
  ~Server();

  uint16_t port() const { return acceptor_.local_endpoint().port(); }
  uint16_t http_port() const;  // 0 without an HTTP listener
  void start();
  // Graceful shutdown: stop accepting, tell every client, persist every session, let the
  // I/O context run dry.
  void stop();

  // For connections.
  std::shared_ptr<Session> find_session(const std::string& name) const override;
  AssetStore& store() override { return *store_; }
  const std::string& instance_name() const override { return config_.name; }
  const ServerConfig& config() const { return config_; }
  void forget(const Connection* connection);
  // A client arrived over another transport (a WebSocket upgraded on the HTTP listener).
  // Refused, with the reason, past the connection caps (overall and per address).
  void adopt(std::unique_ptr<Transport> transport);
  // The call member that was sent voice route `ticket` and has not used it (GET /voice/TICKET
  // on the HTTP listener); null when none (unknown, used, or the member left).
  std::shared_ptr<Connection> voice_ticket_holder(const std::string& ticket) const;
  // Who is taken on: places within the connection caps, joins slowed after wrong tokens.
  Admission& admission() { return admission_; }
  // Sessions people make themselves: rooms, uploaded scenes (SPEC N6-N10).
  SessionMaker& maker() { return *maker_; }
  size_t connection_count() const { return connections_.size(); }
  // Open connections by transport ("tcp", "tls", "websocket") and whether they are in a session.
  std::map<std::pair<std::string, bool>, size_t> connections_by_kind() const;
  ServerCounters& counters() { return counters_; }
  const std::map<std::string, std::shared_ptr<Session>>& sessions() const override { return registry_->all(); }
  void persist(Session& session) { registry_->persist(session); }
  bool stopping() const { return stopping_; }
  asio::io_context& io() override { return io_; }
  std::shared_ptr<asio::ssl::context> tls() const { return tls_; }  // null: plain TCP

  // Changes to sessions go through the relay (one instance, or several through a broker); the
  // relay hands each back to deliver() in the order every instance agrees on.
  Relay& relay() { return *relay_; }
  void deliver(Session& session, const protocol::Message& change, uint64_t sender, std::optional<uint32_t> revision = {}) override;
  // A session defined elsewhere (another instance): stored in the catalogue and served. Null if
  // a session of that name exists or it cannot be stored.
  std::shared_ptr<Session> add_session(StoredSession stored) override { return registry_->add(std::move(stored)); }
  bool remove_session(const std::string& name) override { return registry_->remove(name); }

 private:
  void create_sessions();
  void start_call(Session& session);  // a conference session's call
  void start_face_feeds();
  asio::awaitable<void> persist_loop();
  asio::awaitable<void> call_loop();  // calls' speakers fall silent on time

  asio::io_context& io_;
  ServerConfig config_;
  std::shared_ptr<asio::ssl::context> tls_;
  std::optional<AssetStore> store_;  // opened once the ports are bound
  asio::ip::tcp::acceptor acceptor_;
  asio::steady_timer persist_timer_;
  // The calls' face analysis, on a thread of its own: declared before the sessions, whose calls
  // tell it of members leaving until the last of them is gone.
  std::unique_ptr<CallAnalyst> call_analyst_;
  std::optional<SessionRegistry> registry_;  // made with the store
  std::optional<SessionMaker> maker_;
  std::map<const Connection*, std::shared_ptr<Connection>> connections_;
  Admission admission_{config_};
  std::vector<std::unique_ptr<FaceFeed>> face_feeds_;
  std::unique_ptr<HttpServer> http_;
  std::unique_ptr<Relay> relay_;
  ServerCounters counters_;
  uint64_t next_id_ = 1;
  size_t peak_connections_ = 0;  // since memory was last handed back (persist_loop)
  bool stopping_ = false;
};

}  // namespace inkwire::server
