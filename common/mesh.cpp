#include "common/mesh.hpp"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "common/error.hpp"

namespace inkwire {

glm::vec4 flat_colour(const Mesh& mesh, size_t triangle) {
  const auto& tri = mesh.triangles[triangle];
  const glm::vec4 vertex_mean =
      mesh.has_colours() ? (mesh.colours[tri[0]] + mesh.colours[tri[1]] + mesh.colours[tri[2]]) / 3.0f : glm::vec4(1.0f);
  return vertex_mean * mesh.materials[mesh.material_of(triangle)].base_colour;
}

void validate_mesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw Error("mesh has no triangles");
  if (mesh.positions.empty()) throw Error("mesh has no vertices");
  if (mesh.triangles.size() > kMaxMeshTriangles)
    throw Error("mesh has " + std::to_string(mesh.triangles.size()) + " triangles, more than the limit of " +
                std::to_string(kMaxMeshTriangles));
  if (mesh.positions.size() > kMaxMeshVertices)
    throw Error("mesh has " + std::to_string(mesh.positions.size()) + " vertices, more than the limit of " +
                std::to_string(kMaxMeshVertices));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error("vertex " + std::to_string(i) + " has a non-finite position");
  }
  const size_t n = mesh.positions.size();
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (uint32_t v : mesh.triangles[t])
      if (v >= n)
        throw Error("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) + " but the mesh has only " +
                    std::to_string(n));
  if (!mesh.colours.empty() && mesh.colours.size() != n) throw Error("mesh has colours for some vertices only");
  if (!mesh.corner_uvs.empty() && mesh.corner_uvs.size() != mesh.triangles.size())
    throw Error("mesh has texture coordinates for some triangles only");
  for (const auto& uvs : mesh.corner_uvs)
    for (const glm::vec2& uv : uvs)
      if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) throw Error("mesh has non-finite texture coordinates");
  if (!mesh.triangle_material.empty()) {
    if (mesh.triangle_material.size() != mesh.triangles.size()) throw Error("mesh has materials for some triangles only");
    for (uint32_t m : mesh.triangle_material)
      if (m >= mesh.materials.size()) throw Error("triangle refers to material " + std::to_string(m) + " that does not exist");
  }
}

size_t remove_degenerate_and_unused(Mesh& mesh) {
  size_t kept = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    mesh.triangles[kept] = tri;
    if (!mesh.corner_uvs.empty()) mesh.corner_uvs[kept] = mesh.corner_uvs[t];
    if (!mesh.triangle_material.empty()) mesh.triangle_material[kept] = mesh.triangle_material[t];
    ++kept;
  }
  const size_t dropped = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  if (!mesh.corner_uvs.empty()) mesh.corner_uvs.resize(kept);
  if (!mesh.triangle_material.empty()) mesh.triangle_material.resize(kept);

  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> remap(mesh.positions.size(), kUnused);
  uint32_t next = 0;
  for (auto& tri : mesh.triangles)
    for (uint32_t& v : tri) {
      if (remap[v] == kUnused) remap[v] = next++;
      v = remap[v];
    }
  std::vector<glm::vec3> positions(next);
  std::vector<glm::vec4> colours(mesh.colours.empty() ? 0 : next);
  for (size_t old = 0; old < remap.size(); ++old) {
    if (remap[old] == kUnused) continue;
    positions[remap[old]] = mesh.positions[old];
    if (!colours.empty()) colours[remap[old]] = mesh.colours[old];
  }
  mesh.positions = std::move(positions);
  mesh.colours = std::move(colours);
  return dropped;
}

void normalise(Mesh& mesh, float diagonal) {
  if (mesh.positions.empty()) return;
  glm::vec3 lo = mesh.positions[0], hi = lo;
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 centre = 0.5f * (lo + hi);
  const float current = glm::length(hi - lo);
  const float scale = current > 0.0f ? diagonal / current : 1.0f;
  for (glm::vec3& p : mesh.positions) p = (p - centre) * scale;
}

}  // namespace inkwire
