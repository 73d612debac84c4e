#pragma once
// Who may change what in a session (SPEC W8), decided on the server: clients only show it.
//   - a product (turntable) is read-only to visitors: only an editor presents, changes the style
//     or the pose; visitors keep their own view and may follow a presenter;
//   - a scene that names an editor token lets only editors change style, camera and pose;
//     without one, every member may, as before;
//   - a conference's members publish only as themselves: the session-wide expression comes from
//     the server's own analysis, never from a member; its style is changed by editors when it
//     names an editor token, else by any member.
#include <optional>
#include <string>

#include "protocol/messages.hpp"

namespace inkwire::server {

enum class Role { Visitor, Editor };

struct SessionAuthority {
  protocol::SessionKind kind = protocol::SessionKind::Scene;
  bool has_editor_token = false;
};

// Empty when a member in `role` may send `change` (a state message) to the session; otherwise
// the one-line reason it is refused, which the client shows.
std::string refusal(const SessionAuthority& session, Role role, protocol::MessageType change);

// The role a join's `token` gives, given the digests the session keeps (session_token.hpp):
// the editor token makes an editor (and admits, whatever the session token), the session token
// (or none, when the session names none) a visitor. Nothing when the token is wrong: a token
// given to a session that has no session token is a guess at its editor token.
std::optional<Role> role_of(const std::string& session_token_hash, const std::string& editor_token_hash, const std::string& token);

}  // namespace inkwire::server
