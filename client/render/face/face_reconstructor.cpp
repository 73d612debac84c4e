#include "client/render/face/face_reconstructor.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "common/error.hpp"
#include "common/face/face_mesh.hpp"

namespace inkwire {

FaceReconstructor::FaceReconstructor(const Image& neutral, const FaceLandmarks& landmarks, const ExpressionTemplates& templates,
                                     double tween_seconds)
    : width_(neutral.width),
      height_(neutral.height),
      templates_(templates),
      tween_seconds_(tween_seconds),
      neutral_(landmarks),
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

  Image atlas(width_, height_ + kCavityRows);
  std::copy(neutral.pixels.begin(), neutral.pixels.end(), atlas.pixels.begin());
  const glm::u8vec4 cavity = cavity_colour(neutral, landmarks);
  for (size_t i = neutral.pixels.size(); i < atlas.pixels.size(); i += 4)
    for (int c = 0; c < 4; ++c) atlas.pixels[i + size_t(c)] = cavity[c];
  atlas_ = make_sample_texture(atlas);
  mesh_ = warper_.add_mesh(mesh_points_);
}

void FaceReconstructor::set_expression(ExpressionState state, double now) {
  from_ = landmarks_at(now);
  to_ = apply_expression(neutral_, templates_, state);
  start_ = now;
  target_state_ = state;
}

FaceLandmarks FaceReconstructor::landmarks_at(double now) const {
  const double t = tween_seconds_ > 0 ? std::clamp((now - start_) / tween_seconds_, 0.0, 1.0) : 1.0;
  const float s = float(t * t * (3.0 - 2.0 * t));  // ease in and out
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = glm::mix(from_[i], to_[i], s);
  return out;
}

void FaceReconstructor::render(double now) {
  const FaceLandmarks shown = landmarks_at(now);
  for (size_t i = 0; i < mesh_points_.points.size(); ++i)
    if (landmark_of_[i] >= 0) mesh_points_.points[i][1] = shown[size_t(landmark_of_[i])];
  warper_.update_mesh(mesh_, mesh_points_);
  const WarpSource photo{&atlas_, 0, 1.0f};
  warper_.render(mesh_, {0, 1, 0}, {&photo, 1});
}

}  // namespace inkwire
