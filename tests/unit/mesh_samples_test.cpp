// The truth landmarks are checked against (SPEC T7): whether a sample shows a surface point,
// on a hand-made depth map beside an occluding edge. The cautious test that picks exact control
// points refuses a point with a nearer surface a pixel away; the exact test that checks
// correspondences accepts it, and both refuse a point the nearer surface covers.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "client/render/tween/mesh_samples.hpp"
#include "common/tween/view_sphere.hpp"

using namespace inkwire;

namespace {

constexpr int kSize = 32;

// One sample looking along -Z at a unit box, every pixel showing the surface `far` lies on,
// except the columns from `edge` on, which show one a fifth of a diagonal nearer.
MeshSamples step_sample(const glm::vec3& far, int edge) {
  MeshSamples s;
  s.size = kSize;
  s.distance_diagonals = 1.4f;
  s.bounds = {glm::vec3(-0.5f), glm::vec3(0.5f)};
  s.directions = {glm::vec3(0.0f, 0.0f, 1.0f)};
  s.cameras = {sample_camera(s.bounds, s.directions[0], s.distance_diagonals)};
  const glm::vec3 towards_eye = glm::normalize(s.cameras[0].position - far);
  const float far_depth = s.project(0, far).z;
  const float near_depth = s.project(0, far + 0.2f * s.bounds.diagonal() * towards_eye).z;
  s.depths.assign(1, std::vector<float>(size_t(kSize) * kSize, far_depth));
  for (int y = 0; y < kSize; ++y)
    for (int x = edge; x < kSize; ++x) s.depths[0][size_t(y) * kSize + size_t(x)] = near_depth;
  return s;
}

}  // namespace

TEST(MeshSamplesTest, APointBesideANearerSurfaceIsSeenButNotChosen) {
  const glm::vec3 point(0.05f, 0.03f, 0.2f);  // lands inside a pixel, not on a boundary
  const MeshSamples probe = step_sample(point, kSize);
  const int pixel = int(probe.project(0, point).x);

  const MeshSamples beside = step_sample(point, pixel + 1);  // the nearer surface starts a pixel on
  ASSERT_TRUE(beside.seen_position(0, point).has_value());
  EXPECT_NEAR(beside.seen_position(0, point)->x, probe.project(0, point).x, 1e-4f);
  EXPECT_FALSE(beside.visible_position(0, point).has_value());

  const MeshSamples covered = step_sample(point, pixel);  // the nearer surface covers its pixel
  EXPECT_FALSE(covered.seen_position(0, point).has_value());
  EXPECT_FALSE(covered.visible_position(0, point).has_value());

  const MeshSamples open = step_sample(point, pixel + 2);  // nothing nearer within a pixel
  EXPECT_TRUE(open.seen_position(0, point).has_value());
  EXPECT_TRUE(open.visible_position(0, point).has_value());
}

TEST(MeshSamplesTest, TheTruePositionOfAPixelBesideAnOccludingEdgeIsWhereItProjects) {
  // Two samples of the same view: every pixel of the far surface lands on itself, including
  // the one beside the edge, which the cautious test would have called hidden.
  const glm::vec3 point(0.05f, 0.03f, 0.2f);  // lands inside a pixel, not on a boundary
  const MeshSamples probe = step_sample(point, kSize);
  const glm::vec2 at(probe.project(0, point));
  MeshSamples pair = step_sample(point, int(at.x) + 1);
  pair.directions.push_back(pair.directions[0]);
  pair.cameras.push_back(pair.cameras[0]);
  pair.depths.push_back(pair.depths[0]);
  // The truth a landmark at a pixel is checked against: the surface there, where `to` shows it.
  auto true_position = [&](const glm::vec2& pixel) {
    const std::optional<glm::vec3> surface = pair.surface_point(0, pixel);
    return surface ? pair.seen_position(1, *surface) : std::nullopt;
  };
  const auto truth = true_position(at);
  ASSERT_TRUE(truth.has_value());
  EXPECT_LT(glm::length(*truth - at), 0.01f);
  const auto occluder = true_position(at + glm::vec2(1.0f, 0.0f));  // a pixel of the nearer surface
  ASSERT_TRUE(occluder.has_value());
  EXPECT_LT(glm::length(*occluder - (at + glm::vec2(1.0f, 0.0f))), 0.01f);
}
