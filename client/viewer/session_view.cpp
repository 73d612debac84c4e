#include "client/viewer/session_view.hpp"

#include <algorithm>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>
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
  const glm::quat q(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  return glm::translate(glm::mat4(1.0f), pose.translation) * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), glm::vec3(pose.scale));
}

namespace {

// The cached file of the first asset of `kind`, or an empty path.
std::filesystem::path first_asset_file(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& files,
                                       protocol::AssetKind kind) {
  for (size_t i = 0; i < state.assets.size() && i < files.size(); ++i)
    if (state.assets[i].kind == kind) return files[i];
  return {};
}

}  // namespace

void SessionView::update(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files) {
  state_ = state;
  revision_ = state.revision;
  const bool new_content = state.kind == protocol::SessionKind::Conference ? update_face(state, asset_files)
                           : !state.product.directions.empty()              ? update_product(state)
                                                                           : update_object(state, asset_files);
  update_style(state, new_content);
  if (const auto expression = protocol::expression_state(state.expression); face_ && expression) face_->set_expression(*expression);
}

bool SessionView::update_object(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files) {
  // The first mesh asset is the object.
  const std::filesystem::path mesh = first_asset_file(state, asset_files, protocol::AssetKind::Mesh);
  if (mesh == mesh_file_) return false;
  mesh_file_ = mesh;
  object_.reset();
  content_error_.clear();
  if (!mesh.empty()) {
    try {
      object_ = load_scene_object(mesh, 0, kSceneDiagonal);
    } catch (const Error& e) {
      content_error_ = "cannot load the session's mesh: " + std::string(e.what());
    }
  }
  return true;
}

bool SessionView::update_face(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files) {
  const std::filesystem::path photo = first_asset_file(state, asset_files, protocol::AssetKind::Image);
  const std::filesystem::path landmarks = first_asset_file(state, asset_files, protocol::AssetKind::Landmarks);
  if (photo == face_files_[0] && landmarks == face_files_[1]) return false;
  face_files_[0] = photo, face_files_[1] = landmarks;
  face_.reset();
  content_error_.clear();
  if (photo.empty() || landmarks.empty()) {
    // A call's members show themselves; without them and without a speaker there is nothing.
    if (call_.empty()) content_error_ = "the conference has no speaker yet (no photo and landmarks assets)";
  } else {
    try {
      face_.emplace(photo, landmarks);
    } catch (const Error& e) {
      content_error_ = "cannot show the speaker: " + std::string(e.what());
    }
  }
  return true;
}

bool SessionView::update_product(const protocol::Snapshot& state) {
  if (turntable_ && state.product == product_ && state.assets == product_assets_) return false;
  product_ = state.product;
  product_assets_ = state.assets;
  turntable_.reset();
  object_.reset();
  mesh_file_.clear();
  content_error_.clear();
  try {
    turntable_.emplace(state);
  } catch (const Error& e) {
    content_error_ = "cannot show the product: " + std::string(e.what());
  }
  return true;
}

void SessionView::update_style(const protocol::Snapshot& state, bool new_content) {
  std::string key = state.style.renderer;
  for (const std::string& s : state.style.settings) key += " " + s;
  if (key == style_key_ && !new_content) return;
  // A conference shows the speaker's photo, never a mesh: its style is checked and decides
  // whether the face is painted, but no mesh renderer is made for it.
  const bool shows_object = state.kind != protocol::SessionKind::Conference && !turntable_;
  if (turntable_) turntable_->set_style(state.style.renderer == "tween" ? state.style.settings : std::vector<std::string>{});
  try {
    style_params(state.style.renderer, state.style.settings);
    if (face_) face_->set_style(state.style.renderer, state.style.settings);
    call_.set_style(state.style.renderer, state.style.settings);  // kept for the call's faces to come too
    if (shows_object) {
      auto renderer = make_renderer(state.style.renderer, state.style.settings);
      if (object_) renderer->prepare(*object_);
      renderer_ = std::move(renderer);
    }
    // A product shows on white, as a shop's photos do.
    backdrop_.emplace(BackdropSpec::parse(turntable_ ? "#ffffff" : default_backdrop(state.style.renderer, state.style.settings)));
    style_key_ = key;
    style_error_.clear();
  } catch (const Error& e) {
    style_error_ = "style '" + state.style.renderer + "' refused: " + e.what();
    std::fprintf(stderr, "inkwire-client: %s (keeping the previous style)\n", style_error_.c_str());
    const bool fresh = shows_object ? !renderer_ : !backdrop_;
    if (fresh) {
      // Nothing drawn yet: fall back to the default so the session still shows.
      if (shows_object) renderer_ = make_renderer("default");
      backdrop_.emplace(BackdropSpec::parse(default_backdrop("default")));
    }
    if (object_ && renderer_ && (fresh || new_content)) renderer_->prepare(*object_);
    style_key_ = key;
  }
}

void SessionView::update_call(const protocol::Roster& roster, const std::map<uint16_t, std::vector<std::filesystem::path>>& files) {
  call_.update(roster, files);
  if (!call_.empty() && !face_) content_error_.clear();
}

std::optional<ExpressionState> SessionView::expression() const {
  if (!face_) return std::nullopt;
  return face_->expression();
}

void SessionView::draw(glm::ivec2 viewport, double time_seconds, long frame) {
  if (!backdrop_) backdrop_.emplace(BackdropSpec::parse("paper"));
  backdrop_->draw();
  if (!call_.empty()) call_.draw(viewport, time_seconds, face_ ? &*face_ : nullptr);
  else if (face_) face_->draw(viewport, time_seconds);
  if (turntable_) turntable_->draw(viewport, orbit_);
  if (!object_ || !renderer_) return;
  FrameState f;
  f.viewport = viewport;
  f.camera = camera_from(state_.camera);
  f.model = model_matrix(state_.object);
  f.light_direction = default_light_direction(f.camera);
  f.time_seconds = time_seconds;
  f.frame = frame;
  f.backdrop = &*backdrop_;
  renderer_->draw(f);
}

}  // namespace inkwire
