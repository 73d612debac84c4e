#pragma once
// Builds a Mesh from the vertices of any reader (assimp natively, the GLB reader in the browser):
// equal positions are welded into one, so the topology is real (SPEC G1), and both readers of the
// same model give the same mesh.
#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_map>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "common/mesh.hpp"

namespace inkwire {

class MeshWelder {
 public:
  // The index of position `p`, new or one already added (-0 and 0 are one).
  uint32_t weld(const glm::vec3& p);
  // The welded vertex's colour: the last one given for any vertex welded into it.
  void set_colour(uint32_t vertex, const glm::vec4& colour);
  // A triangle of welded indices, its corners' texture coordinates (when the source has them)
  // and its material (an index into materials()).
  void add_triangle(const std::array<uint32_t, 3>& corners, const std::array<glm::vec2, 3>& uvs, bool has_uvs, uint32_t material);
  std::vector<Material>& materials() { return mesh_.materials; }
  // The mesh: colours, texture coordinates and materials dropped when no vertex or triangle had
  // any (one material or none: no per-triangle materials).
  Mesh take();

 private:
  struct PositionKey {
    float x, y, z;
    bool operator==(const PositionKey& o) const { return std::memcmp(this, &o, sizeof(*this)) == 0; }
  };
  struct PositionHash {
    size_t operator()(const PositionKey& k) const;
  };
  Mesh mesh_;
  std::unordered_map<PositionKey, uint32_t, PositionHash> index_of_;
  bool any_colour_ = false, any_uv_ = false;
};

}  // namespace inkwire
