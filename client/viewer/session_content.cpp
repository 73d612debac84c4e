#include "client/viewer/session_content.hpp"

#include <glm/gtc/quaternion.hpp>

#include "client/render/styles.hpp"
#include "common/error.hpp"

namespace inkwire {

protocol::CameraPose camera_pose(const Camera& camera, uint32_t sequence) {
  return {.sequence = sequence, .position = camera.position, .target = camera.target, .up = camera.up, .fov_y_degrees = camera.fov_y_degrees};
}

Camera camera_from(const protocol::CameraPose& pose) { return scene_camera(pose.position, pose.target, pose.up, pose.fov_y_degrees); }

protocol::CameraPose orbit_pose(float azimuth_degrees, float elevation_degrees, float distance_diagonals, uint32_t sequence) {
  return camera_pose(scene_orbit_camera(azimuth_degrees, elevation_degrees, distance_diagonals), sequence);
}

glm::mat4 model_matrix(const protocol::ObjectPose& pose) {
  return pose_matrix(pose.translation, glm::quat(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z), pose.scale);
}

namespace {

// The cached file of the first asset of `kind`, or an empty path.
std::filesystem::path first_asset_file(const protocol::Snapshot& state, const AssetFiles& files, protocol::AssetKind kind) {
  for (size_t i = 0; i < state.assets.size() && i < files.size(); ++i)
    if (state.assets[i].kind == kind) return files[i];
  return {};
}

}  // namespace

bool SceneContent::update(const protocol::Snapshot& state, const AssetFiles& files) {
  // The first mesh asset is the object.
  const std::filesystem::path mesh = first_asset_file(state, files, protocol::AssetKind::Mesh);
  if (mesh == mesh_file_) return false;
  mesh_file_ = mesh;
  object_.reset();
  error_.clear();
  if (!mesh.empty()) {
    try {
      object_ = load_scene_object(mesh, 0, kSceneDiagonal);
    } catch (const Error& e) {
      error_ = "cannot load the session's mesh: " + std::string(e.what());
    }
  }
  return true;
}

void SceneContent::set_style(const protocol::StyleChange& style) {
  auto renderer = make_renderer(style.renderer, style.settings);
  if (object_) renderer->prepare(*object_);
  renderer_ = std::move(renderer);
}

void SceneContent::keep_after_refusal(bool new_content) {
  const bool fresh = !renderer_;
  if (fresh) renderer_ = make_renderer("default");
  if (object_ && (fresh || new_content)) renderer_->prepare(*object_);
}

std::string SceneContent::backdrop(const protocol::StyleChange& style) const { return default_backdrop(style.renderer, style.settings); }

void SceneContent::draw(glm::ivec2 viewport, double time_seconds, long frame, const protocol::Snapshot& state, const Backdrop& backdrop) {
  if (!object_ || !renderer_) return;
  renderer_->draw(scene_frame(viewport, camera_from(state.camera), model_matrix(state.object), time_seconds, frame, &backdrop));
}

bool ConferenceContent::update(const protocol::Snapshot& state, const AssetFiles& files) {
  if (const auto expression = protocol::expression_state(state.expression); face_ && expression) face_->set_expression(*expression);
  const std::filesystem::path photo = first_asset_file(state, files, protocol::AssetKind::Image);
  const std::filesystem::path landmarks = first_asset_file(state, files, protocol::AssetKind::Landmarks);
  if (photo == face_files_[0] && landmarks == face_files_[1]) return false;
  face_files_[0] = photo, face_files_[1] = landmarks;
  face_.reset();
  error_.clear();
  if (photo.empty() || landmarks.empty()) {
    // A call's members show themselves; without them and without a speaker there is nothing.
    if (call_.empty()) error_ = "the conference has no speaker yet (no photo and landmarks assets)";
  } else {
    try {
      face_.emplace(photo, landmarks);
      if (const auto expression = protocol::expression_state(state.expression)) face_->set_expression(*expression);
    } catch (const Error& e) {
      error_ = "cannot show the speaker: " + std::string(e.what());
    }
  }
  return true;
}

void ConferenceContent::update_call(const protocol::Roster& roster, const std::map<uint16_t, AssetFiles>& files) {
  call_.update(roster, files);
  if (!call_.empty() && !face_) error_.clear();
}

void ConferenceContent::set_style(const protocol::StyleChange& style) {
  // The speaker's photo, never a mesh: the style decides how the face is drawn.
  if (face_) face_->set_style(style.renderer, style.settings);
  call_.set_style(style.renderer, style.settings);  // kept for the call's faces to come too
}

std::string ConferenceContent::backdrop(const protocol::StyleChange& style) const { return default_backdrop(style.renderer, style.settings); }

void ConferenceContent::draw(glm::ivec2 viewport, double time_seconds, long, const protocol::Snapshot&, const Backdrop&) {
  if (!call_.empty()) call_.draw(viewport, time_seconds, face_ ? &*face_ : nullptr);
  else if (face_) face_->draw(viewport, time_seconds);
}

bool ProductContent::update(const protocol::Snapshot& state, const AssetFiles&) {
  if (turntable_ && state.product == product_ && state.assets == assets_) return false;
  product_ = state.product;
  assets_ = state.assets;
  turntable_.reset();
  error_.clear();
  try {
    turntable_.emplace(state);
  } catch (const Error& e) {
    error_ = "cannot show the product: " + std::string(e.what());
  }
  return true;
}

void ProductContent::set_style(const protocol::StyleChange& style) {
  if (turntable_) turntable_->set_style(style.renderer == "tween" ? style.settings : std::vector<std::string>{});
}

void ProductContent::draw(glm::ivec2 viewport, const TurntableOrbit& orbit) {
  if (turntable_) turntable_->draw(viewport, orbit);
}

}  // namespace inkwire
