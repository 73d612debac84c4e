#include "common/orientation.hpp"

namespace inkwire {

size_t classify_faces(const Mesh& mesh, const Topology& topology, const glm::vec3& eye, std::vector<uint8_t>& front) {
  front.resize(mesh.triangles.size());
  size_t count = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    front[t] = faces_eye(topology.face_normals[t], mesh.positions[mesh.triangles[t][0]], eye);
    count += front[t];
  }
  return count;
}

}  // namespace inkwire
