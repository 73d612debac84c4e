#pragma once
// Draws a session's state locally (SPEC N5): the content its kind names (session_content.hpp: a
// scene's object in the session's style from the session's camera and object pose, a
// conference's faces, a product turned by this visitor's own view) over the style's backdrop.
// Objects are centred and scaled to kSceneDiagonal, the scene space in which camera and object
// poses travel. Needs a current GL context; draws into whatever framebuffer is bound.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "client/viewer/session_content.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class SessionView {
 public:
  // Takes the latest state and the cached files of its assets (same order). Loads new content
  // when its assets change and remakes the renderer when the style changes. A style this client
  // cannot make (unknown name, bad setting) is reported by error() and the previous one is kept,
  // so one bad change never blanks the picture.
  void update(const protocol::Snapshot& state, const AssetFiles& asset_files);
  void draw(glm::ivec2 viewport, double time_seconds, long frame);

  // Why the mesh, the speaker or the style could not be shown; empty when all is well.
  const std::string& error() const { return content_error().empty() ? style_error_ : content_error(); }
  // Why the session's content (mesh, speaker, product) is not shown; empty when it is.
  const std::string& content_error() const;
  uint32_t revision() const { return state_.revision; }
  const std::string& style() const { return style_key_; }
  // The expression shown, in conference sessions.
  std::optional<ExpressionState> expression() const;
  // A conference's painted face: frames painted since its style was set (ConferenceView).
  int painted_frames() const;

  // A call (a conference whose members publish themselves): the roster with its members'
  // cached photo and landmarks files, and each member's face as it is due.
  void update_call(const protocol::Roster& roster, const std::map<uint16_t, AssetFiles>& files);
  void set_member_face(const protocol::MemberLayers& face) { conference().call().set_face(face); }
  const CallGrid& call() const;

  // A turntable session's product (null in other sessions), and this visitor's own view of it
  // (kept whatever the session shows, so it may be set before the product arrives).
  TurntableView* turntable();
  TurntableOrbit& orbit() { return orbit_; }

 private:
  // The conference content, made when a roster comes before the session's state.
  ConferenceContent& conference();
  void update_style(const protocol::Snapshot& state, bool new_content);

  std::variant<std::monostate, SceneContent, ConferenceContent, ProductContent> content_;
  TurntableOrbit orbit_;
  std::optional<Backdrop> backdrop_;
  std::string style_key_, style_error_;
  protocol::Snapshot state_;
};

}  // namespace inkwire
