#pragma once
// How a change to a session's state reaches its members: on one
// instance it is applied and forwarded at once (LocalRelay); with several instances it goes
// through a broker, which orders it among every instance's changes and brings it to all of them
// (RedisRelay). Connections and face feeds only ever call publish(); they never know which.
#include <cstdint>
#include <memory>
#include <string>

#include "protocol/messages.hpp"
#include "server/relay/broker_formats.hpp"

namespace inkwire::server {

class Session;
class SessionFanout;

// What /healthz and /metrics say of the relay.
struct RelayStatus {
  bool broker = false;     // a broker is configured
  bool connected = true;   // ... and reachable now (always true without one)
  uint64_t published = 0;  // changes handed to the broker
  uint64_t received = 0;   // changes that came back from it (from every instance)
  uint64_t resyncs = 0;    // sessions read whole from the broker (after a gap or an outage)
  uint64_t reconnects = 0;
  size_t outbox = 0;       // changes made while the broker was away, waiting to go out
  double lag_seconds = 0;  // last time from publishing a change to its coming back
  uint64_t overflows = 0;  // sessions whose changes waiting for a resync overflowed (then read whole)
};

class Relay {
 public:
  virtual ~Relay() = default;
  virtual void start() = 0;
  virtual void stop() = 0;
  // A change (style, camera, object pose, expression) to `session` made by the member with
  // connection id `sender` (0: the server itself). Every member but the sender gets it, on
  // every instance, in the same order everywhere.
  virtual void publish(Session& session, const protocol::Message& change, uint64_t sender) = 0;
  virtual RelayStatus status() const = 0;
  // A call's traffic for the members on other instances (call/call.hpp); nothing to do alone.
  virtual void share_call(const CallShare& share) { (void)share; }
  // A session made while the server runs (a room opened, a scene uploaded), and one gone: the
  // other instances hear of it; nothing to do alone. A product or scene removed is removed on
  // every instance; a call room gone idle here is gone here only (members elsewhere keep theirs).
  virtual void session_added(const Session& session) { (void)session; }
  virtual void session_removed(const Session& session) { (void)session; }
  // A running scene given a new model (its editor's upload): the other instances' members get it
  // too; nothing to do alone.
  virtual void model_replaced(const Session& session) { (void)session; }
};

// The relay a config's "broker" asks for: local without one, Redis for "redis://HOST:PORT".
// Throws inkwire::Error for a broker this build cannot use.
std::unique_ptr<Relay> make_relay(SessionFanout& sessions, const std::string& broker);

}  // namespace inkwire::server
