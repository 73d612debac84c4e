// Level of detail through meshoptimizer (SPEC G4): the study's face counts from a real mesh.
#include <gtest/gtest.h>

#include "common/lod.hpp"
#include "common/mesh_import.hpp"
#include "common/topology.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

TEST(LodTest, BullReachesTheStudysFaceCounts) {
  const auto file = cgal_mesh("bull.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh bull = load_mesh(file);
  for (size_t target : {578u, 870u, 1284u, 2162u, 5488u, 10648u}) {
    SCOPED_TRACE(target);
    const Mesh lod = simplify_to_faces(bull, target);
    // Within 2% of the requested count: the series must roughly halve step by step.
    EXPECT_NEAR(double(lod.face_count()), double(target), 0.02 * target);
    EXPECT_NO_THROW(validate_mesh(lod));
    const Topology topo = build_topology(lod);
    EXPECT_EQ(topo.boundary_edges, 0u) << "simplification must keep the mesh closed";
  }
}

TEST(LodTest, TargetAboveInputReturnsInput) {
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh cow = load_mesh(file);
  EXPECT_EQ(simplify_to_faces(cow, cow.face_count() + 10).face_count(), cow.face_count());
}

TEST(LodTest, UvsSurviveSimplification) {
  const auto file = kAssimpModels / "OBJ/WusonOBJ.obj";
  INKWIRE_REQUIRE_FILE(file);
  const Mesh mesh = load_mesh(file);
  const Mesh lod = simplify_to_faces(mesh, mesh.face_count() / 2);
  EXPECT_EQ(lod.has_uvs(), mesh.has_uvs());
  EXPECT_LE(lod.face_count(), mesh.face_count() / 2 + 1);
}

TEST(LodTest, LevelsHalveFacesAndGrowInError) {
  const auto file = cgal_mesh("bull.off");
  INKWIRE_REQUIRE_FILE(file);
  const Mesh bull = load_mesh(file);
  const MeshLevels levels(bull, build_topology(bull));
  ASSERT_GE(levels.size(), 4u);
  EXPECT_EQ(levels[0].error, 0.0f);
  for (size_t i = 1; i < levels.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT(levels[i].mesh.face_count(), levels[i - 1].mesh.face_count());
    EXPECT_GE(levels[i].error, levels[i - 1].error);
    EXPECT_GT(levels[i].error, 0.0f);
  }
  // Far away (few pixels per unit) the coarsest level is good enough; close up only the full mesh.
  EXPECT_EQ(&levels.pick(1e-6f, 0.5f), &levels[levels.size() - 1]);
  EXPECT_EQ(&levels.pick(1e9f, 0.5f), &levels[0]);
}
