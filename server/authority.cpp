#include "server/authority.hpp"

#include "server/session_token.hpp"

namespace inkwire::server {

using protocol::MessageType;
using protocol::SessionKind;

std::string refusal(const SessionAuthority& session, Role role, MessageType change) {
  if (role == Role::Editor) return {};
  const std::string what = change == MessageType::StyleChange ? "change the style"
                           : change == MessageType::ObjectPose ? "present or turn the object"
                           : change == MessageType::CameraPose ? "move the camera"
                                                               : "send expression codes";
  switch (session.kind) {
    case SessionKind::Turntable:
      return "only the product's editor may " + what + " here; your view is your own, and you may follow a presenter";
    case SessionKind::Conference:
      if (change == MessageType::ExpressionCode || change == MessageType::ObjectPose || change == MessageType::CameraPose)
        return "members publish only as themselves: faces come from each member's own camera";
      // A call's editor is its host: who opened the room (its host key), or who holds the config's editor token.
      if (session.has_editor_token) return "only the call's host may " + what + " for everyone";
      return {};
    case SessionKind::Scene:
      if (session.has_editor_token) return "only the session's editors may " + what + "; you follow them";
      return {};
  }
  return "unknown session kind";
}

std::optional<Role> role_of(const std::string& session_token_hash, const std::string& editor_token_hash, const std::string& token) {
  // Both comparisons always run, so the time an answer takes does not say which matched.
  const bool editor = !editor_token_hash.empty() && token_matches(editor_token_hash, token);
  const bool visitor = token_matches(session_token_hash, token);
  if (editor) return Role::Editor;
  if (session_token_hash.empty() && !token.empty() && !editor_token_hash.empty()) return std::nullopt;
  if (visitor) return Role::Visitor;
  return std::nullopt;
}

}  // namespace inkwire::server
