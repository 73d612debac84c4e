#pragma once
// What a relay (relay.hpp) needs of the sessions it serves, and nothing more: find one or list
// them, hand a change back to be applied and forwarded to its members in the order the relay
// decided, serve a session defined on another instance, read and store the assets sessions
// name, this instance's name and its I/O context. The server is one; a test's own could be
// another, so the relay's rules can run without sockets.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <asio/io_context.hpp>

#include "protocol/messages.hpp"

namespace inkwire::server {

class AssetStore;
class Session;
struct StoredSession;

class SessionFanout {
 public:
  virtual ~SessionFanout() = default;
  virtual std::shared_ptr<Session> find_session(const std::string& name) const = 0;
  virtual const std::map<std::string, std::shared_ptr<Session>>& sessions() const = 0;
  // Applies `change` (from connection `sender`, 0: none) and forwards it to the session's
  // members; `revision`, with a broker, is the broker's count of the session's changes.
  virtual void deliver(Session& session, const protocol::Message& change, uint64_t sender, std::optional<uint32_t> revision = {}) = 0;
  // A session defined elsewhere, stored and served; null when one of that name exists or it cannot be stored.
  virtual std::shared_ptr<Session> add_session(StoredSession stored) = 0;
  // A session removed on another instance (remove-product, remove-scene) stops being served here
  // and leaves the store; false when none of that name is served.
  virtual bool remove_session(const std::string& name) = 0;
  virtual AssetStore& store() = 0;
  virtual const std::string& instance_name() const = 0;
  virtual asio::io_context& io() = 0;
};

}  // namespace inkwire::server
