// Meshes that cannot be drawn safely are refused with one line (SPEC X2).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/mesh.hpp"

using namespace inkwire;

namespace {

Mesh triangle() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  m.materials.emplace_back();
  return m;
}

void expect_refused(const Mesh& m, const std::string& reason_part) {
  try {
    validate_mesh(m);
    ADD_FAILURE() << "accepted a mesh that should fail with '" << reason_part << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(reason_part), std::string::npos) << e.what();
  }
}

}  // namespace

TEST(MeshValidateTest, GoodTriangleIsAccepted) { EXPECT_NO_THROW(validate_mesh(triangle())); }

TEST(MeshValidateTest, EmptyIsRefused) {
  Mesh m = triangle();
  m.triangles.clear();
  expect_refused(m, "no triangles");
}

TEST(MeshValidateTest, NonFinitePositionsAreRefused) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    Mesh m = triangle();
    m.positions[1].y = bad;
    expect_refused(m, "non-finite");
  }
}

TEST(MeshValidateTest, OutOfRangeIndexIsRefused) {
  Mesh m = triangle();
  m.triangles[0][2] = 3;
  expect_refused(m, "refers to vertex 3");
}

TEST(MeshValidateTest, MismatchedAttributesAreRefused) {
  Mesh m = triangle();
  m.colours = {glm::vec4(1.0f)};
  expect_refused(m, "colours");
  m = triangle();
  m.triangle_material = {4};
  expect_refused(m, "material 4");
}

TEST(MeshValidateTest, DegenerateAndUnusedAreRemoved) {
  Mesh m = triangle();
  m.positions.push_back({5, 5, 5});  // unused
  m.triangles.push_back({0, 0, 1});  // degenerate
  EXPECT_EQ(remove_degenerate_and_unused(m), 1u);
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.face_count(), 1u);
}
