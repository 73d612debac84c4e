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

Camera camera_from(const protocol::CameraPose& pose) {
  Camera c;
  c.position = pose.position;
  c.target = pose.target;
  c.up = pose.up;
  c.fov_y_degrees = pose.fov_y_degrees;
  const float distance = glm::length(pose.position);
  c.near_plane = std::max(distance - kSceneDiagonal, std::max(distance * 0.02f, 0.01f));
  c.far_plane = distance + kSceneDiagonal;
  return c;
}

protocol::CameraPose orbit_pose(float azimuth_degrees, float elevation_degrees, float distance_diagonals, uint32_t sequence) {
  return camera_pose(scene_orbit_camera(azimuth_degrees, elevation_degrees, distance_diagonals), sequence);
}

glm::mat4 model_matrix(const protocol::ObjectPose& pose) {
  const glm::quat q(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  return glm::translate(glm::mat4(1.0f), pose.translation) * glm::mat4_cast(q) * glm::scale(glm::mat4(1.0f), glm::vec3(pose.scale));
}

void SessionView::update(const protocol::Snapshot& state, const std::vector<std::filesystem::path>& asset_files) {
  state_ = state;
  revision_ = state.revision;
  // The first mesh asset is the object (conference sessions have none).
  std::filesystem::path mesh;
  for (size_t i = 0; i < state.assets.size() && i < asset_files.size(); ++i)
    if (state.assets[i].kind == protocol::AssetKind::Mesh) {
      mesh = asset_files[i];
      break;
    }
  const bool new_object = mesh != mesh_file_;
  if (new_object) {
    mesh_file_ = mesh;
    object_.reset();
    if (!mesh.empty()) {
      try {
        object_ = load_scene_object(mesh, 0, kSceneDiagonal);
      } catch (const Error& e) {
        error_ = "cannot load the session's mesh: " + std::string(e.what());
      }
    }
  }
  std::string key = state.style.renderer;
  for (const std::string& s : state.style.settings) key += " " + s;
  if (key == style_key_ && !new_object) return;
  try {
    auto renderer = make_renderer(state.style.renderer, state.style.settings);
    if (object_) renderer->prepare(*object_);
    renderer_ = std::move(renderer);
    backdrop_.emplace(BackdropSpec::parse(default_backdrop(state.style.renderer)));
    style_key_ = key;
    error_.clear();
  } catch (const Error& e) {
    error_ = "style '" + state.style.renderer + "' refused: " + e.what();
    std::fprintf(stderr, "inkwire-client: %s (keeping the previous style)\n", error_.c_str());
    const bool fresh = !renderer_;
    if (fresh) {
      // Nothing drawn yet: fall back to the default so the session still shows.
      renderer_ = make_renderer("default");
      backdrop_.emplace(BackdropSpec::parse(default_backdrop("default")));
    }
    if (object_ && (fresh || new_object)) renderer_->prepare(*object_);
    style_key_ = key;
  }
}

void SessionView::draw(glm::ivec2 viewport, double time_seconds, long frame) {
  if (!backdrop_) backdrop_.emplace(BackdropSpec::parse("paper"));
  backdrop_->draw();
  if (!object_ || !renderer_) return;
  FrameState f;
  f.viewport = viewport;
  f.camera = camera_from(state_.camera);
  f.model = model_matrix(state_.object);
  f.light_direction = default_light_direction(f.camera);
  f.time_seconds = time_seconds;
  f.frame = frame;
  renderer_->draw(f);
}

}  // namespace inkwire
