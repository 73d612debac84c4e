#pragma once
// What a session shows, one class for each kind of session (SessionView holds the one its
// snapshot names): a scene's object in the session's style, a conference's speaker and call
// members' faces, a product's photos turned by the visitor's own view. Each takes the state and
// the cached files of its assets, reports whether what it draws was replaced and why its content
// cannot be shown, takes the session's style (throwing inkwire::Error for one it cannot make)
// and draws over the backdrop SessionView laid.
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

using AssetFiles = std::vector<std::filesystem::path>;  // the cached file of each of a state's assets, in order

// A shared scene: the first mesh asset, centred and scaled to kSceneDiagonal, drawn by the
// style's renderer from the session's camera and object pose.
class SceneContent {
 public:
  bool update(const protocol::Snapshot& state, const AssetFiles& files);
  void set_style(const protocol::StyleChange& style);
  // A style refused: the renderer as it was (given a new object), or the default one when none
  // was made yet, so the scene still shows.
  void keep_after_refusal(bool new_content);
  std::string backdrop(const protocol::StyleChange& style) const;
  void draw(glm::ivec2 viewport, double time_seconds, long frame, const protocol::Snapshot& state, const Backdrop& backdrop);
  const std::string& error() const { return error_; }

 private:
  std::optional<SceneObject> object_;
  std::filesystem::path mesh_file_;
  std::unique_ptr<Renderer> renderer_;
  std::string error_;
};

// A conference: the speaker's face from its photo and landmarks assets, rebuilt from expression
// codes, and a call's members (CallGrid) when they publish themselves.
class ConferenceContent {
 public:
  bool update(const protocol::Snapshot& state, const AssetFiles& files);
  void update_call(const protocol::Roster& roster, const std::map<uint16_t, AssetFiles>& files);
  void set_style(const protocol::StyleChange& style);
  void keep_after_refusal(bool) {}
  std::string backdrop(const protocol::StyleChange& style) const;
  void draw(glm::ivec2 viewport, double time_seconds, long, const protocol::Snapshot&, const Backdrop&);
  const std::string& error() const { return error_; }

  std::optional<ExpressionState> expression() const { return face_ ? std::optional(face_->expression()) : std::nullopt; }
  int painted_frames() const { return face_ ? face_->painted_frames() : 0; }
  CallGrid& call() { return call_; }
  const CallGrid& call() const { return call_; }

 private:
  std::optional<ConferenceView> face_;
  std::filesystem::path face_files_[2];  // photo, landmarks
  CallGrid call_;
  std::string error_;
};

// A product: its photos and tween data (TurntableView), on white as a shop's photos are.
class ProductContent {
 public:
  bool update(const protocol::Snapshot& state, const AssetFiles& files);
  void set_style(const protocol::StyleChange& style);
  void keep_after_refusal(bool) {}
  std::string backdrop(const protocol::StyleChange&) const { return "#ffffff"; }
  void draw(glm::ivec2 viewport, const TurntableOrbit& orbit);
  const std::string& error() const { return error_; }
  TurntableView* turntable() { return turntable_ ? &*turntable_ : nullptr; }
  const TurntableView* turntable() const { return turntable_ ? &*turntable_ : nullptr; }

 private:
  std::optional<TurntableView> turntable_;
  protocol::Product product_;
  std::vector<protocol::AssetAnnounce> assets_;
  std::string error_;
};

}  // namespace inkwire
