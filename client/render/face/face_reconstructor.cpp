#include "client/render/face/face_reconstructor.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "common/error.hpp"
#include "common/face/face_mesh.hpp"

namespace inkwire {
namespace {

constexpr float kFarBehind = -10.0f;  // what does not turn (the image border) lies behind everything that does

}  // namespace

FaceReconstructor::FaceReconstructor(const Image& neutral, const FaceLandmarks& landmarks, const ExpressionTemplates& templates,
                                     double tween_seconds)
    : width_(neutral.width),
      height_(neutral.height),
      templates_(templates),
      tween_seconds_(tween_seconds),
      neutral_(landmarks),
      frame_(face_frame(landmarks)),
      warper_(neutral.width, neutral.height),
      from_(landmarks),
      to_(landmarks) {
  if (neutral.width < 16 || neutral.height < 16) throw Error("face reconstruction: the neutral photo is too small");
  for (const glm::vec2& p : landmarks)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.x < 0 || p.y < 0 || p.x > float(neutral.width) || p.y > float(neutral.height))
      throw Error("face reconstruction: a landmark lies outside the photo");
  FaceMesh face_mesh = build_face_mesh(landmarks, templates, width_, height_);
  mesh_points_ = std::move(face_mesh.mesh);
  landmark_of_ = std::move(face_mesh.landmark_of);
  head_point_ = std::move(face_mesh.head_point);
  follows_ = std::move(face_mesh.follows);
  triangles_ = mesh_points_.triangles;

  Image atlas(width_, height_ + kCavityRows);
  std::copy(neutral.pixels.begin(), neutral.pixels.end(), atlas.pixels.begin());
  const glm::u8vec4 cavity = cavity_colour(neutral, landmarks);
  for (size_t i = neutral.pixels.size(); i < atlas.pixels.size(); i += 4)
    for (int c = 0; c < 4; ++c) atlas.pixels[i + size_t(c)] = cavity[c];
  atlas_ = make_sample_texture(atlas);
  mesh_ = warper_.add_mesh(mesh_points_);
}

void FaceReconstructor::set_face(const FaceState& state, double now) {
  from_ = layered_at(now);
  from_pose_ = pose_at(now);
  to_ = apply_layers(neutral_, templates_, state.layers);
  to_pose_ = state.pose;
  start_ = now;
  target_ = state;
  target_code_ = dominant_expression(state.layers);
}

void FaceReconstructor::set_expression(ExpressionState state, double now) {
  set_face({.layers = layers_of(state, templates_), .pose = target_.pose}, now);
  target_code_ = state;
}

float FaceReconstructor::tween(double now) const {
  const double t = tween_seconds_ > 0 ? std::clamp((now - start_) / tween_seconds_, 0.0, 1.0) : 1.0;
  return float(t * t * (3.0 - 2.0 * t));  // ease in and out
}

FaceLandmarks FaceReconstructor::layered_at(double now) const {
  const float s = tween(now);
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = glm::mix(from_[i], to_[i], s);
  return out;
}

HeadPose FaceReconstructor::pose_at(double now) const { return mix(from_pose_, to_pose_, tween(now)); }

FaceLandmarks FaceReconstructor::landmarks_at(double now) const {
  const FaceLandmarks layered = layered_at(now);
  const glm::mat3 rotation = rotation_of(pose_at(now));
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = frame_.to_image(glm::vec2(turned(glm::vec3(frame_.to_face(layered[i]), head_point_[i].z), rotation)));
  return out;
}

void FaceReconstructor::render(double now) {
  const FaceLandmarks layered = layered_at(now);
  const glm::mat3 rotation = rotation_of(pose_at(now));
  std::vector<float> depth(mesh_points_.points.size());
  for (size_t i = 0; i < mesh_points_.points.size(); ++i) {
    glm::vec3 head = head_point_[i];
    if (landmark_of_[i] >= 0) head = glm::vec3(frame_.to_face(layered[size_t(landmark_of_[i])]), head.z);
    const glm::vec3 at = turned(head, rotation);
    glm::vec2 drawn = frame_.to_image(glm::vec2(at));
    // What turns only part way (the neck) or not at all (the border) stays that much where it was.
    if (follows_[i] < 1.0f) drawn = glm::mix(mesh_points_.points[i][0], drawn, follows_[i]);
    mesh_points_.points[i][1] = drawn;
    depth[i] = follows_[i] * at.z + (1.0f - follows_[i]) * kFarBehind;
  }
  warper_.update_mesh(mesh_, mesh_points_);
  // Nearest first: the first triangle to reach a pixel is the one drawn there.
  std::vector<std::array<uint32_t, 3>> order = triangles_;
  const auto nearness = [&](const std::array<uint32_t, 3>& t) { return depth[t[0]] + depth[t[1]] + depth[t[2]]; };
  std::stable_sort(order.begin(), order.end(), [&](const auto& a, const auto& b) { return nearness(a) > nearness(b); });
  if (order != triangles_) {
    triangles_ = std::move(order);
    warper_.update_triangles(mesh_, triangles_);
  }
  const WarpSource photo{&atlas_, 0, 1.0f};
  warper_.render(mesh_, {0, 1, 0}, {&photo, 1});
}

}  // namespace inkwire
