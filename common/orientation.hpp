#pragma once
// Face and edge classification (SPEC G3) and the study's fast orientation methods (C5, C6).
//
// G3: a triangle is front-facing when the view vector and its normal point against each other;
// a silhouette edge joins a front and a back triangle.
// C5: with one constant view vector V (viewer to bounding-box centre) the test is per triangle
// N.V < 0, which misses faces near the viewer; the perspective correction widens it to
// N.V < sin(alpha), sin(alpha) = a / |V| with a the largest bounding-box side.
// C6: classify vertices instead (N_v.V < sin(alpha)) and draw a triangle when at least k of
// its three vertices are front-facing.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "common/mesh.hpp"
#include "common/topology.hpp"

namespace inkwire {

// Exact per-triangle test: the eye sees the face's front when it lies on the normal's side of
// the face's plane.
inline bool faces_eye(const glm::vec3& normal, const glm::vec3& point_on_face, const glm::vec3& eye) {
  return glm::dot(normal, eye - point_on_face) > 0.0f;
}

// Fills `front` (one flag per triangle) for an eye given in the mesh's own coordinates and
// returns how many triangles are front-facing.
size_t classify_faces(const Mesh& mesh, const Topology& topology, const glm::vec3& eye_object,
                      std::vector<uint8_t>& front);

inline bool is_silhouette(const Edge& e, const std::vector<uint8_t>& front) {
  return e.f1 != kNoFace && front[e.f0] != front[e.f1];
}

enum class Orientation {
  Triangle,           // constant view vector, N.V < 0
  TriangleCorrected,  // constant view vector, N.V < sin(alpha)
  TriangleExact,      // exact view vector per triangle (G3)
  Vertex,             // vertices by N_v.V < sin(alpha), triangles with >= k front vertices
};

// "triangle", "triangle-corrected", "triangle-exact", "vertex". Throws inkwire::Error otherwise.
Orientation parse_orientation(const std::string& name);
std::string to_string(Orientation o);

// The per-frame quantities the fast methods share, all in the mesh's own coordinates.
struct ViewSetup {
  glm::vec3 eye;             // viewer position
  glm::vec3 view;            // unit constant view vector, viewer to bounding-box centre
  float sin_alpha;           // perspective correction, a / |V|, clamped to 1
  static ViewSetup from(const Topology& topology, const glm::vec3& eye_object);
};

// What the vertex method needs beyond the study's rule to promise no holes with k = 1,
// computed once per mesh.
//
// The study's rule (N_v.V < sin(alpha)) can leave holes on coarse or sharp meshes: a face can
// pass the corrected triangle test while all three of its vertex normals, averaged with faces
// that turn away, fail it. Each face therefore appoints the vertex whose normal is closest to
// its own. When that distance d = |N_v - N_f| is small, the vertex's threshold grows by d;
// since N_v.V <= N_f.V + d, the face then always keeps a front vertex. Faces whose every vertex
// normal is farther than `max_margin` away (ridges, spikes) would inflate thresholds for all
// their neighbours, so instead they are tested on their own with the corrected triangle test.
struct VertexMargins {
  std::vector<float> margin;                // per vertex
  std::vector<uint32_t> tested_per_face;    // faces with no vertex normal close to their own
};
VertexMargins vertex_margins(const Mesh& mesh, const Topology& topology, float max_margin = 0.1f);

// Chooses the triangles to draw by `method` (k is used by Vertex only: 1, 2 or 3), filling
// `draw` with one flag per triangle and returning how many are drawn. `vertex_front` is
// scratch space (one flag per vertex) for the vertex method; `margins` (or null for the
// study's plain threshold) makes k = 1 hole-free as described above.
size_t orient_triangles(Orientation method, int k, const Mesh& mesh, const Topology& topology, const ViewSetup& view,
                        std::vector<uint8_t>& draw, std::vector<uint8_t>& vertex_front,
                        const VertexMargins* margins = nullptr);

}  // namespace inkwire
