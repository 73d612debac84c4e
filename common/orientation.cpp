#include "common/orientation.hpp"

#include <algorithm>

#include "common/error.hpp"

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

Orientation parse_orientation(const std::string& name) {
  if (name == "triangle") return Orientation::Triangle;
  if (name == "triangle-corrected") return Orientation::TriangleCorrected;
  if (name == "triangle-exact") return Orientation::TriangleExact;
  if (name == "vertex") return Orientation::Vertex;
  throw Error("orientation '" + name + "' is not triangle, triangle-corrected, triangle-exact or vertex");
}

std::string to_string(Orientation o) {
  switch (o) {
    case Orientation::Triangle: return "triangle";
    case Orientation::TriangleCorrected: return "triangle-corrected";
    case Orientation::TriangleExact: return "triangle-exact";
    case Orientation::Vertex: return "vertex";
  }
  return "?";
}

ViewSetup ViewSetup::from(const Topology& topology, const glm::vec3& eye) {
  const glm::vec3 to_centre = topology.bounds.centre() - eye;
  const float distance = glm::length(to_centre);
  ViewSetup v;
  v.eye = eye;
  v.view = distance > 0.0f ? to_centre / distance : glm::vec3(0.0f, 0.0f, -1.0f);
  // Inside the bounding box the constant vector says nothing useful: keep everything.
  v.sin_alpha = distance > 0.0f ? std::min(1.0f, topology.bounds.largest_side() / distance) : 1.0f;
  return v;
}

VertexMargins vertex_margins(const Mesh& mesh, const Topology& topology, float max_margin) {
  VertexMargins m;
  m.margin.assign(mesh.positions.size(), 0.0f);
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const glm::vec3& face = topology.face_normals[t];
    uint32_t closest = mesh.triangles[t][0];
    float distance = 3.0f;
    for (uint32_t v : mesh.triangles[t]) {
      const float d = glm::length(topology.vertex_normals[v] - face);
      if (d < distance) distance = d, closest = v;
    }
    if (distance <= max_margin) m.margin[closest] = std::max(m.margin[closest], distance);
    else m.tested_per_face.push_back(t);
  }
  return m;
}

size_t orient_triangles(Orientation method, int k, const Mesh& mesh, const Topology& topology, const ViewSetup& view,
                        std::vector<uint8_t>& draw, std::vector<uint8_t>& vertex_front, const VertexMargins* margins) {
  const size_t n = mesh.triangles.size();
  draw.resize(n);
  size_t count = 0;
  switch (method) {
    case Orientation::Triangle:
    case Orientation::TriangleCorrected: {
      // N.V < threshold: V points from the viewer into the scene, so a face toward the viewer
      // has a negative N.V.
      const float threshold = method == Orientation::Triangle ? 0.0f : view.sin_alpha;
      for (size_t t = 0; t < n; ++t) count += draw[t] = glm::dot(topology.face_normals[t], view.view) < threshold;
      return count;
    }
    case Orientation::TriangleExact: return classify_faces(mesh, topology, view.eye, draw);
    case Orientation::Vertex: {
      if (k < 1 || k > 3) throw Error("vertex orientation needs k = 1, 2 or 3");
      vertex_front.resize(mesh.positions.size());
      if (margins && margins->margin.size() != mesh.positions.size()) throw Error("vertex margins do not match the mesh");
      for (size_t v = 0; v < mesh.positions.size(); ++v)
        vertex_front[v] = glm::dot(topology.vertex_normals[v], view.view) < view.sin_alpha + (margins ? margins->margin[v] : 0.0f);
      for (size_t t = 0; t < n; ++t) {
        const auto& tri = mesh.triangles[t];
        const int front = vertex_front[tri[0]] + vertex_front[tri[1]] + vertex_front[tri[2]];
        count += draw[t] = front >= k;
      }
      if (margins && k == 1)
        for (uint32_t t : margins->tested_per_face)
          if (!draw[t] && glm::dot(topology.face_normals[t], view.view) < view.sin_alpha) count += draw[t] = 1;
      return count;
    }
  }
  return count;
}

}  // namespace inkwire
