#include "client/render/sketch/sketch_edges.hpp"

#include <glm/geometric.hpp>

namespace inkwire {

void choose_sketch_edges(const Mesh& mesh, const Topology& topology, const std::vector<uint32_t>& candidates,
                         const glm::vec3& eye, float crease_radians, const FadeOptions& fade, std::vector<DrawnEdge>& out) {
  out.clear();
  for (uint32_t i : candidates) {
    const Edge& e = topology.edges[i];
    const glm::vec3 mid = 0.5f * (mesh.positions[e.v0] + mesh.positions[e.v1]);
    const glm::vec3 to_eye = glm::normalize(eye - mid);
    const float d1 = glm::dot(topology.face_normals[e.f0], to_eye);
    if (e.boundary) {
      out.push_back({i, 1.0f});
      continue;
    }
    const float d2 = glm::dot(topology.face_normals[e.f1], to_eye);
    if (e.dihedral > crease_radians && (d1 > 0.0f || d2 > 0.0f)) {
      out.push_back({i, 1.0f});
      continue;
    }
    const float opacity = fade_opacity(d1, d2, fade);
    if (opacity > 0.0f) out.push_back({i, opacity});
  }
}

}  // namespace inkwire
