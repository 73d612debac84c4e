#pragma once
// Face and edge classification (SPEC G3): a triangle is front-facing when the view vector and
// its normal point against each other; a silhouette edge joins a front and a back triangle.
#include <cstdint>
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

}  // namespace inkwire
