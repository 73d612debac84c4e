#pragma once
// Sessions shared by several server instances through Redis (SPEC D1; the layout in
// docs/deploy.md "What the broker holds"):
// - A change goes to Redis, where one script stores it in the session's state hash, counts it
//   in the session's revision and publishes it; every instance, the sender's own included,
//   applies changes in the order of those revisions, so all agree. A gap in the revisions, a
//   late start or a return of the broker reads the session's state whole (a resync).
// - Sessions and their assets are shared too: an instance puts its sessions' definitions and
//   asset bytes into Redis, and makes sessions it lacks from there, each asset checked against
//   its hash before it is stored.
// - While the broker is away an instance serves its own members as a single instance would,
//   keeps the latest change of each kind per session, publishes them when the broker is back
//   (reconnecting with back-off) and then resynchronises.
// All of it runs on the server's I/O thread through asynchronous hiredis calls.
#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <asio.hpp>

#include "server/relay/broker_formats.hpp"
#include "server/relay/change_order.hpp"
#include "server/relay/redis_connection.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {

struct StoredSession;

struct BrokerAddress {
  std::string host;
  uint16_t port = 6379;
  std::string user, password;  // AUTH on connecting, when a password is given
};
// "redis://[[USER]:PASSWORD@]HOST[:PORT]". Throws inkwire::Error for anything else, naming what
// this build can use.
BrokerAddress parse_broker(const std::string& url);

class RedisRelay final : public Relay {
 public:
  RedisRelay(SessionFanout& sessions, BrokerAddress address);
  ~RedisRelay() override;
  void start() override;
  void stop() override;
  void publish(Session& session, const protocol::Message& change, uint64_t sender) override;
  RelayStatus status() const override;
  void share_call(const CallShare& share) override;
  void session_added(const Session& session) override;
  void session_removed(const Session& session) override;
  void model_replaced(const Session& session) override;

 private:
  void removed_elsewhere(const std::string& name);
  std::optional<StoredSession> read_definition(const std::string& name, std::string_view definition);
  using Event = BrokerEvent;
  struct Unsent {
    protocol::Bytes frame;
    uint64_t sender = 0;
  };

  void connect();
  void lost(const std::string& reason);
  void on_subscription(const redisReply* reply);
  void ready();
  void send_change(const std::string& session, const std::string& field, const protocol::Bytes& frame, uint64_t sender, bool by_digest = true);
  void keep_unsent(const std::string& session, const std::string& field, const protocol::Bytes& frame, uint64_t sender);
  void on_event(std::string_view payload);
  void on_call(std::string_view payload);
  // What the session's order asked of an arriving change: applied, counted as dropped, resynced.
  void follow(Session& session, ChangeOrder& order, ChangeOrder::Arrival arrival);
  void resync(const std::string& session);
  void retry_resync(const std::string& session);
  void heartbeat();
  void share(const Session& session);
  void share_asset(const protocol::AssetAnnounce& asset);
  void discover();
  // A session's definition as the broker holds it: a session this instance lacks is adopted, a
  // scene it serves whose model the definition changed takes the new model.
  void take_definition(const std::string& name, std::string_view definition);
  void adopt_remote(const std::string& name, std::string_view value);
  void adopt_model(const std::string& name, std::string_view definition, StoredSession stored);
  // The assets of `assets` this instance lacks, fetched from the broker and stored (each checked
  // against its hash); then `done(true)`, or `done(false)` once one could not be had.
  void fetch_missing(const std::string& name, const std::vector<protocol::AssetAnnounce>& assets, std::function<void(bool)> done);

  SessionFanout& sessions_;
  BrokerAddress address_;
  asio::io_context& io_;
  RedisConnection commands_, events_;
  asio::steady_timer retry_timer_, heartbeat_timer_;
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kHeartbeatDeadline{3000};
  bool ping_outstanding_ = false;
  uint64_t ping_round_ = 0;
  Clock::time_point ping_sent_;
  std::chrono::milliseconds backoff_{100};
  int connections_up_ = 0, subscriptions_ = 0;
  bool ready_ = false, retry_scheduled_ = false, stopped_ = false, ever_ready_ = false;
  std::map<std::string, ChangeOrder> orders_;  // each session's changes from the broker, in order
  std::map<std::pair<std::string, std::string>, Unsent> unsent_;  // (session, field): latest wins
  std::set<std::string> adopting_;                                 // remote sessions whose assets are on their way
  std::map<std::string, std::string> definitions_;                 // each session's definition as the broker holds it
  RelayStatus status_;
  std::string publish_digest_;  // SHA-1 of the publish script, for EVALSHA
};

}  // namespace inkwire::server
