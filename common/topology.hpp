#pragma once
// Topology built once at load time (SPEC G2): unique edges with their adjacent triangles,
// dihedral angle and length; triangle and vertex normals; bounds. Inface edges (two coplanar
// triangles) are dropped; open and non-manifold edges are kept and flagged.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "common/mesh.hpp"

namespace inkwire {

inline constexpr uint32_t kNoFace = 0xffffffffu;

struct Edge {
  uint32_t v0, v1;       // v0 < v1
  uint32_t f0, f1;       // adjacent triangles; f1 == kNoFace on an open (boundary) edge
  float dihedral;        // angle between the two face normals, radians; 0 = flat; pi on a boundary
  float length;
  bool boundary;         // only one adjacent triangle
  bool non_manifold;     // three or more adjacent triangles (f0, f1 are the first two)
};

struct Bounds {
  glm::vec3 min{0.0f}, max{0.0f};
  glm::vec3 centre() const { return 0.5f * (min + max); }
  glm::vec3 size() const { return max - min; }
  float diagonal() const;
  float largest_side() const;
};

struct Topology {
  std::vector<Edge> edges;                // kept edges (inface edges dropped)
  std::vector<glm::vec3> face_normals;    // unit, per triangle (zero for zero-area triangles)
  std::vector<glm::vec3> vertex_normals;  // unit average of adjacent face normals
  Bounds bounds;
  size_t inface_edges_dropped = 0;
  size_t boundary_edges = 0;
  size_t non_manifold_edges = 0;

  size_t unique_edge_count() const { return edges.size() + inface_edges_dropped; }
};

// Two triangles count as coplanar (their shared edge is "inface") below this dihedral angle.
inline constexpr float kInfaceAngleRadians = 1e-4f;

Topology build_topology(const Mesh& mesh);

Bounds compute_bounds(const std::vector<glm::vec3>& positions);

}  // namespace inkwire
