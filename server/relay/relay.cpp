#include "server/relay/relay.hpp"

#include "common/error.hpp"
#include "server/relay/redis_relay.hpp"
#include "server/relay/session_fanout.hpp"

namespace inkwire::server {
namespace {

// One instance: a change is applied and forwarded where it was made.
class LocalRelay final : public Relay {
 public:
  explicit LocalRelay(SessionFanout& sessions) : sessions_(sessions) {}
  void start() override {}
  void stop() override {}
  void publish(Session& session, const protocol::Message& change, uint64_t sender) override { sessions_.deliver(session, change, sender); }
  RelayStatus status() const override { return {}; }

 private:
  SessionFanout& sessions_;
};

}  // namespace

std::unique_ptr<Relay> make_relay(SessionFanout& sessions, const std::string& broker) {
  if (broker.empty()) return std::make_unique<LocalRelay>(sessions);
  const BrokerAddress address = parse_broker(broker);
  return std::make_unique<RedisRelay>(sessions, address);
}

}  // namespace inkwire::server
