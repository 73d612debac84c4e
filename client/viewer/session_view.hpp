#pragma once
// Draws a session's state locally (SPEC N5): the object from the cached mesh asset, in the
// session's style, from the session's camera and object pose. Objects are centred and scaled to
// kSceneDiagonal, the scene space in which camera and object poses travel. A conference session
// shows the speaker's face instead (ConferenceView). Needs a current GL context; draws into
// whatever framebuffer is bound.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client/call/call_grid.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/renderer.hpp"
#include "client/render/scene_object.hpp"
#include "client/render/face/conference_view.hpp"
#include "client/viewer/turntable_view.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

// Camera poses on the wire and cameras for renderers. Near and far planes follow from the
// distance to the target in a scene of kSceneDiagonal.
protocol::CameraPose camera_pose(const Camera& camera, uint32_t sequence = 0);
Camera camera_from(const protocol::CameraPose& pose);
// A camera orbiting the scene's centre (azimuth about +Y from +Z, distance in scene diagonals).
protocol::CameraPose orbit_pose(float azimuth_degrees, float elevation_degrees, float distance_diagonals, uint32_t sequence = 0);
glm::mat4 model_matrix(const protocol::ObjectPose& pose);

class SessionView {
 public:
  // Takes the latest state and the cached files of its assets (same order). Loads a new mesh
  // when the mesh asset changes and remakes the renderer when the style changes. A style this
  // client cannot make (unknown name, bad setting) is reported by error() and the previous one
  // is kept, so one bad change never blanks the picture.
  void update(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files);
  void draw(glm::ivec2 viewport, double time_seconds, long frame);

  // Why the mesh, the speaker or the style could not be shown; empty when all is well.
  const std::string& error() const { return content_error_.empty() ? style_error_ : content_error_; }
  // Why the session's content (mesh, speaker, product) is not shown; empty when it is.
  const std::string& content_error() const { return content_error_; }
  uint32_t revision() const { return revision_; }
  const std::string& style() const { return style_key_; }
  // The expression shown, in conference sessions.
  std::optional<ExpressionState> expression() const;
  // A conference's painted face: frames painted since its style was set (ConferenceView).
  int painted_frames() const { return face_ ? face_->painted_frames() : 0; }

  // A call (a conference whose members publish themselves): the roster with its members'
  // cached photo and landmarks files, and each member's face as it is due.
  void update_call(const protocol::Roster& roster, const std::map<uint16_t, std::vector<std::filesystem::path>>& files);
  void set_member_face(const protocol::MemberFace& face) { call_.set_face(face); }
  const CallGrid& call() const { return call_; }

  // A turntable session's product and this visitor's own view of it (null in other sessions).
  TurntableView* turntable() { return turntable_ ? &*turntable_ : nullptr; }
  TurntableOrbit& orbit() { return orbit_; }

 private:
  // Each returns true when what it draws was replaced.
  bool update_object(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files);
  bool update_face(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files);
  bool update_product(const protocol::Snapshot& state);
  void update_style(const protocol::Snapshot& state, bool new_content);

  std::optional<SceneObject> object_;
  std::filesystem::path mesh_file_;
  std::optional<ConferenceView> face_;
  CallGrid call_;
  std::optional<TurntableView> turntable_;
  protocol::Product product_;
  std::vector<protocol::AssetAnnounce> product_assets_;
  TurntableOrbit orbit_;
  std::filesystem::path face_files_[2];  // photo, landmarks
  std::unique_ptr<Renderer> renderer_;
  std::optional<Backdrop> backdrop_;
  std::string style_key_, content_error_, style_error_;
  protocol::Snapshot state_;
  uint32_t revision_ = 0;
};

}  // namespace inkwire
