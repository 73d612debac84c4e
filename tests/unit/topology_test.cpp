// Topology on real packaged meshes and small constructed ones (SPEC G2).
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "common/mesh_import.hpp"
#include "common/topology.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

namespace {

// An axis-aligned unit box, 12 triangles, written with each side's four corners repeated (as
// exporters with per-face normals do) so the importer's welding is exercised too.
const char* kBoxObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3\nf 1 3 2\n"   // z = 0, facing -z
    "f 5 6 7\nf 5 7 8\n"   // z = 1
    "f 1 2 6\nf 1 6 5\n"   // y = 0
    "f 4 8 7\nf 4 7 3\n"   // y = 1
    "f 1 5 8\nf 1 8 4\n"   // x = 0
    "f 2 3 7\nf 2 7 6\n";  // x = 1

size_t euler(const Mesh& mesh, const Topology& topo) {
  return mesh.positions.size() - topo.unique_edge_count() + mesh.face_count();
}

}  // namespace

TEST(TopologyTest, ClosedGenusZeroMeshesHaveTwoFacesPerEdge) {
  // (cow.off is not used here: it has two vertices at one position, which welding joins into
  // a pinch, so its Euler characteristic is honestly 1.)
  for (const char* name : {"bull.off", "camel.off", "triceratops.off"}) {
    SCOPED_TRACE(name);
    const auto file = cgal_mesh(name);
    INKWIRE_REQUIRE_FILE(file);
    const Mesh mesh = load_mesh(file);
    const Topology topo = build_topology(mesh);
    EXPECT_EQ(topo.boundary_edges, 0u);
    EXPECT_EQ(topo.non_manifold_edges, 0u);
    for (const Edge& e : topo.edges) ASSERT_NE(e.f1, kNoFace);
    EXPECT_EQ(euler(mesh, topo), 2u) << "V - E + F";
    // Every triangle has three edges, each shared by two: 2E = 3F.
    EXPECT_EQ(2 * topo.unique_edge_count(), 3 * mesh.face_count());
  }
}

TEST(TopologyTest, HoleReportsItsBoundaryEdges) {
  const auto file = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(file);
  Mesh mesh = load_mesh(file);
  mesh.triangles.erase(mesh.triangles.begin() + 100);  // punch a one-triangle hole
  const Topology topo = build_topology(mesh);
  EXPECT_EQ(topo.boundary_edges, 3u);
  for (const Edge& e : topo.edges) EXPECT_EQ(e.boundary, e.f1 == kNoFace);
}

TEST(TopologyTest, OpenShellFromPackageHasBoundary) {
  const std::filesystem::path cat = "/usr/share/glmark2/models/cat.3ds";
  INKWIRE_REQUIRE_FILE(cat);
  const Topology topo = build_topology(load_mesh(cat));
  EXPECT_GT(topo.boundary_edges, 0u);
}

TEST(TopologyTest, BoxWithSplitSidesKeepsItsTwelveRealEdges) {
  const Mesh mesh = load_mesh(write_temp("box.obj", kBoxObj));
  const Topology topo = build_topology(mesh);
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(topo.unique_edge_count(), 18u);
  EXPECT_EQ(topo.inface_edges_dropped, 6u);  // one diagonal per side
  ASSERT_EQ(topo.edges.size(), 12u);
  for (const Edge& e : topo.edges) {
    EXPECT_NEAR(e.dihedral, std::numbers::pi / 2, 1e-5);
    EXPECT_NEAR(e.length, 1.0f, 1e-6);
  }
  EXPECT_EQ(euler(mesh, topo), 2u);
}

TEST(TopologyTest, NormalsAndBounds) {
  const Mesh mesh = load_mesh(write_temp("box_normals.obj", kBoxObj));
  const Topology topo = build_topology(mesh);
  EXPECT_EQ(topo.bounds.min, glm::vec3(0.0f));
  EXPECT_EQ(topo.bounds.max, glm::vec3(1.0f));
  EXPECT_NEAR(topo.bounds.diagonal(), std::sqrt(3.0f), 1e-6);
  for (size_t t = 0; t < mesh.face_count(); ++t) {
    // Outward: the normal points away from the box centre.
    const glm::vec3 p = mesh.positions[mesh.triangles[t][0]];
    EXPECT_GT(glm::dot(topo.face_normals[t], p - glm::vec3(0.5f)), 0.0f) << "triangle " << t;
  }
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(topo.vertex_normals[v]), 1.0f, 1e-5);
    EXPECT_GT(glm::dot(topo.vertex_normals[v], mesh.positions[v] - glm::vec3(0.5f)), 0.0f);
  }
}

TEST(TopologyTest, NonManifoldEdgeIsFlaggedNotFatal) {
  // Three triangles sharing one edge (a "book" with three pages).
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  mesh.materials.emplace_back();
  const Topology topo = build_topology(mesh);
  EXPECT_EQ(topo.non_manifold_edges, 1u);
  EXPECT_EQ(topo.boundary_edges, 6u);
}
