#include "common/mesh_welder.hpp"

namespace inkwire {

size_t MeshWelder::PositionHash::operator()(const PositionKey& k) const {
  uint32_t b[3];
  std::memcpy(b, &k, sizeof(b));
  return (size_t(b[0]) * 73856093u) ^ (size_t(b[1]) * 19349663u) ^ (size_t(b[2]) * 83492791u);
}

uint32_t MeshWelder::weld(const glm::vec3& p) {
  const PositionKey key{p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};  // +0 folds -0 into 0
  auto [it, inserted] = index_of_.try_emplace(key, uint32_t(mesh_.positions.size()));
  if (inserted) {
    mesh_.positions.push_back(p);
    mesh_.colours.emplace_back(1.0f);
  }
  return it->second;
}

void MeshWelder::set_colour(uint32_t vertex, const glm::vec4& colour) {
  mesh_.colours[vertex] = colour;
  any_colour_ = true;
}

void MeshWelder::add_triangle(const std::array<uint32_t, 3>& corners, const std::array<glm::vec2, 3>& uvs, bool has_uvs, uint32_t material) {
  mesh_.triangles.push_back(corners);
  mesh_.corner_uvs.push_back(has_uvs ? uvs : std::array<glm::vec2, 3>{});
  mesh_.triangle_material.push_back(material);
  any_uv_ = any_uv_ || has_uvs;
}

Mesh MeshWelder::take() {
  if (!any_colour_) mesh_.colours.clear();
  if (!any_uv_) mesh_.corner_uvs.clear();
  if (mesh_.materials.size() <= 1) mesh_.triangle_material.clear();
  return std::move(mesh_);
}

}  // namespace inkwire
