#pragma once
// A session as the catalogue (asset_store.hpp) and the broker (relay/broker_formats.hpp) keep it:
// who may join and edit, its last state, and who made it.
#include <cstdint>
#include <string>

#include "protocol/messages.hpp"

namespace inkwire::server {

// Who made a session (SPEC N6-N9): the operator (its config, add-product), a visitor who opened a
// call room or uploaded a model, or `add-scene`. Sessions people make on demand go when unused
// (server/making/session_maker.hpp) unless kept.
enum class MadeBy : uint8_t { Operator = 0, Room = 1, Upload = 2, Command = 3 };
const char* to_string(MadeBy maker);
MadeBy made_by_from_string(const std::string& name);  // throws inkwire::Error

struct StoredSession {
  std::string token;  // hash_token() of the session's token (session_token.hpp); empty: anyone may join
  std::string editor_token;  // hash_token() of the token that makes a member an editor (authority.hpp); empty: none
  protocol::Snapshot state;
  MadeBy maker = MadeBy::Operator;
  std::string creator;  // the address that made it, for the caps per address (made on demand only)
  bool kept = false;    // kept however long it goes unused (made on demand only)
  // Made on demand and gone when unused long enough.
  bool expires() const { return (maker == MadeBy::Room || maker == MadeBy::Upload) && !kept; }
};

}  // namespace inkwire::server
