#include "client/viewer/turntable_view.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include "client/render/styles.hpp"
#include "client/render/tween/matte_sample.hpp"
#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/tween/view_sphere.hpp"

namespace inkwire {

glm::vec3 TurntableOrbit::direction() const {
  const float az = glm::radians(azimuth), el = glm::radians(elevation);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

TurntableOrbit TurntableOrbit::from_direction(const glm::vec3& d) {
  return {.azimuth = glm::degrees(std::atan2(d.x, d.z)), .elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)))};
}

protocol::ObjectPose TurntableOrbit::pose(uint32_t sequence) const {
  // Turning by -azimuth about the vertical, then by elevation about the horizontal, brings this
  // view's direction to the first sample's (0, 0, 1).
  const glm::quat turn = glm::angleAxis(glm::radians(elevation), glm::vec3(1, 0, 0)) *
                         glm::angleAxis(glm::radians(-azimuth), glm::vec3(0, 1, 0));
  return {.sequence = sequence, .rotation = {turn.x, turn.y, turn.z, turn.w}, .translation = glm::vec3(0.0f), .scale = zoom};
}

TurntableOrbit TurntableOrbit::from_pose(const protocol::ObjectPose& pose) {
  // The decoder has checked the rotation is a unit quaternion and the scale positive.
  const glm::quat turn(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  TurntableOrbit view = from_direction(glm::normalize(glm::conjugate(turn) * glm::vec3(0, 0, 1)));
  view.zoom = std::clamp(pose.scale, kMinZoom, kMaxZoom);
  return view;
}

TurntableView::TurntableView(const protocol::Snapshot& state) : product_(state.product) {
  if (product_.directions.size() < 2) throw Error("session '" + state.session + "' has no product to show");
  // The rows' elevations, lowest first (directions travel as i16: rows within half a degree are one).
  for (const glm::vec3& d : product_.directions) row_heights_.push_back(TurntableOrbit::from_direction(d).elevation);
  std::sort(row_heights_.begin(), row_heights_.end());
  row_heights_.erase(std::unique(row_heights_.begin(), row_heights_.end(), [](float a, float b) { return b - a < 0.5f; }), row_heights_.end());
  TweenModel header;
  header.data.width = product_.width;
  header.data.height = product_.height;
  header.data.directions = product_.directions;
  header.distance_diagonals = product_.distance_diagonals;
  header.fov_y_degrees = product_.fov_y_degrees;
  // The photos looked at the centre of a box one scene diagonal across.
  const float half = kSceneDiagonal / (2.0f * std::sqrt(3.0f));
  header.bounds = {.min = glm::vec3(-half), .max = glm::vec3(half)};
  renderer_.configure(style_params("tween").front());
  renderer_.begin_model(std::move(header));
  has_.assign(product_.directions.size(), false);
  set_style(state.style.renderer == "tween" ? state.style.settings : std::vector<std::string>{});
}

void TurntableView::set_style(const std::vector<std::string>& settings) {
  try {
    renderer_.configure(style_params("tween", settings).front());
  } catch (const Error& e) {
    error_ = std::string("tween settings refused: ") + e.what();
  }
}

glm::vec2 TurntableView::elevation_range() const { return {row_heights_.front(), row_heights_.back()}; }

float TurntableView::row_elevation(float elevation, int rows) const {
  const auto nearest = std::min_element(row_heights_.begin(), row_heights_.end(), [&](float a, float b) {
    return std::abs(a - elevation) < std::abs(b - elevation);
  });
  const long index = std::clamp(long(nearest - row_heights_.begin()) + rows, 0L, long(row_heights_.size()) - 1);
  return row_heights_[size_t(index)];
}

int TurntableView::nearest_sample(const TurntableOrbit& orbit) const { return inkwire::nearest_sample(product_.directions, orbit.direction()); }

int TurntableView::wanted_level(const TurntableOrbit& orbit) const {
  std::vector<int> level_heights;
  for (const auto& level : product_.levels) level_heights.push_back(level.height);
  // The photos' height on the display, as draw() shows them.
  return inkwire::wanted_level(product_.height, level_heights, double(display_.y) * double(orbit.zoom));
}

std::optional<PhotoFetch> TurntableView::next_fetch(const TurntableOrbit& orbit) const {
  const glm::vec3 d = orbit.direction();
  return next_photo_fetch(product_.directions, d, renderer_.view_samples(d), has_, finer_level_, wanted_level(orbit));
}

glm::vec2 TurntableView::sample_angles(int index) const {
  const TurntableOrbit view = TurntableOrbit::from_direction(product_.directions.at(size_t(index)));
  return {view.azimuth, view.elevation};
}

Image TurntableView::sample_image(const std::filesystem::path& photo, const std::filesystem::path& matte) {
  if (matte.empty()) return load_image(photo);
  try {
    return object_on_matte(load_image(photo), load_image(matte));
  } catch (const Error& e) {
    throw Error(matte.filename().string() + ": " + e.what());
  }
}

void TurntableView::add_sample(int index, const Image& image, int level) {
  if (index < 0 || index >= samples()) throw Error("sample " + std::to_string(index) + " is not in the product");
  if (level < 0 || level > int(product_.levels.size())) throw Error("the product has no zoom level " + std::to_string(level));
  const glm::ivec2 size = level == 0 ? glm::ivec2(product_.width, product_.height)
                                     : glm::ivec2(product_.levels[size_t(level - 1)].width, product_.levels[size_t(level - 1)].height);
  if (image.width != size.x || image.height != size.y)
    throw Error("sample " + std::to_string(index) + " at level " + std::to_string(level) + " is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ", not " + std::to_string(size.x) + "x" + std::to_string(size.y));
  if (level == 0) {
    renderer_.set_sample(index, image);
    if (!has_[size_t(index)]) ++loaded_;
    has_[size_t(index)] = true;
    return;
  }
  renderer_.set_finer_sample(index, image);
  finer_level_[index] = level;
  if (const int drop = finer_to_drop(product_.directions, index, finer_level_); drop >= 0) {
    renderer_.drop_finer_sample(drop);
    finer_level_.erase(drop);
  }
}

void TurntableView::add_cells(const std::map<uint16_t, protocol::Bytes>& cells) {
  for (const auto& [index, bytes] : cells) {
    if (cells_seen_.count(index)) continue;
    cells_seen_[index] = true;
    try {
      renderer_.add_cell(decode_tween_cell(bytes, product_.width, product_.height, samples()));
    } catch (const Error& e) {
      error_ = "tween cell " + std::to_string(index) + " refused: " + e.what();
    }
  }
}

void TurntableView::draw(glm::ivec2 viewport, const TurntableOrbit& orbit) {
  display_ = viewport;
  renderer_.use_finer(wanted_level(orbit) > 0);
  FrameState f;
  f.viewport = viewport;
  const float distance = product_.distance_diagonals * kSceneDiagonal / std::max(orbit.zoom, 0.05f);
  f.camera.position = orbit.direction() * distance;
  f.camera.target = glm::vec3(0.0f);
  f.camera.up = std::abs(orbit.elevation) > 89.0f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  f.camera.fov_y_degrees = product_.fov_y_degrees;
  renderer_.draw(f);
}

}  // namespace inkwire
