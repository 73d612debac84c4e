#include "common/topology.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace inkwire {

float Bounds::diagonal() const { return glm::length(size()); }
float Bounds::largest_side() const {
  const glm::vec3 s = size();
  return std::max({s.x, s.y, s.z});
}

Bounds compute_bounds(const std::vector<glm::vec3>& positions) {
  Bounds b;
  if (positions.empty()) return b;
  b.min = b.max = positions[0];
  for (const glm::vec3& p : positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

Topology build_topology(const Mesh& mesh) {
  Topology topo;
  topo.bounds = compute_bounds(mesh.positions);

  topo.face_normals.resize(mesh.triangles.size());
  topo.vertex_normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const glm::vec3 n = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                   mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    const float len = glm::length(n);
    topo.face_normals[t] = len > 0.0f ? n / len : glm::vec3(0.0f);
    for (uint32_t v : tri) topo.vertex_normals[v] += topo.face_normals[t];
  }
  for (glm::vec3& n : topo.vertex_normals) {
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
  }

  // Gather the faces around every undirected edge, keyed by its sorted vertex pair.
  struct Adjacent {
    uint32_t f0 = kNoFace, f1 = kNoFace;
    uint32_t count = 0;
  };
  std::unordered_map<uint64_t, Adjacent> by_key;
  by_key.reserve(mesh.triangles.size() * 2);
  std::vector<uint64_t> order;  // first-seen order keeps edge numbering deterministic
  order.reserve(mesh.triangles.size() * 3 / 2);
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = std::min(tri[c], tri[(c + 1) % 3]);
      const uint32_t b = std::max(tri[c], tri[(c + 1) % 3]);
      const uint64_t key = (uint64_t(a) << 32) | b;
      auto [it, inserted] = by_key.try_emplace(key);
      if (inserted) order.push_back(key);
      Adjacent& adj = it->second;
      if (adj.count == 0) adj.f0 = t;
      else if (adj.count == 1) adj.f1 = t;
      ++adj.count;
    }
  }

  topo.edges.reserve(order.size());
  for (uint64_t key : order) {
    const Adjacent& adj = by_key[key];
    Edge e;
    e.v0 = uint32_t(key >> 32);
    e.v1 = uint32_t(key & 0xffffffffu);
    e.f0 = adj.f0;
    e.f1 = adj.f1;
    e.length = glm::length(mesh.positions[e.v1] - mesh.positions[e.v0]);
    e.boundary = adj.count == 1;
    e.non_manifold = adj.count > 2;
    if (e.boundary) {
      e.dihedral = std::numbers::pi_v<float>;
    } else {
      // atan2 keeps precision for nearly flat edges, where acos of a dot product loses it.
      const glm::vec3& n0 = topo.face_normals[e.f0];
      const glm::vec3& n1 = topo.face_normals[e.f1];
      e.dihedral = std::atan2(glm::length(glm::cross(n0, n1)), glm::dot(n0, n1));
    }
    if (!e.boundary && !e.non_manifold && e.dihedral < kInfaceAngleRadians) {
      ++topo.inface_edges_dropped;
      continue;
    }
    topo.boundary_edges += e.boundary;
    topo.non_manifold_edges += e.non_manifold;
    topo.edges.push_back(e);
  }
  return topo;
}

}  // namespace inkwire
