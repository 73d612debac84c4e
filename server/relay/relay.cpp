#include "server/relay/relay.hpp"

#include "common/error.hpp"
#include "server/relay/redis_relay.hpp"
#include "server/server.hpp"

namespace inkwire::server {
namespace {

// One instance: a change is applied and forwarded where it was made.
class LocalRelay final : public Relay {
 public:
  explicit LocalRelay(Server& server) : server_(server) {}
  void start() override {}
  void stop() override {}
  void publish(Session& session, const protocol::Message& change, uint64_t sender) override { server_.deliver(session, change, sender); }
  RelayStatus status() const override { return {}; }

 private:
  Server& server_;
};

}  // namespace

std::unique_ptr<Relay> make_relay(Server& server, const ServerConfig& config) {
  if (config.broker.empty()) return std::make_unique<LocalRelay>(server);
  const BrokerAddress address = parse_broker(config.broker);
  return std::make_unique<RedisRelay>(server, address);
}

}  // namespace inkwire::server
