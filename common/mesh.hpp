#pragma once
// A triangle mesh as every renderer sees it (SPEC G1): welded positions and triangles are
// guaranteed; colours, texture coordinates and materials are optional.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace inkwire {

struct Material {
  std::string name;
  glm::vec4 base_colour{0.8f, 0.8f, 0.8f, 1.0f};
  // Diffuse / base-colour texture file, empty when untextured. Embedded textures are written
  // nowhere: their encoded bytes are kept in `texture_bytes` instead.
  std::filesystem::path texture_file;
  std::vector<unsigned char> texture_bytes;
  bool textured() const { return !texture_file.empty() || !texture_bytes.empty(); }
};

struct Mesh {
  std::vector<glm::vec3> positions;                 // welded: one entry per distinct position
  std::vector<std::array<uint32_t, 3>> triangles;   // counter-clockwise when seen from outside
  std::vector<glm::vec4> colours;                   // per position, or empty
  std::vector<std::array<glm::vec2, 3>> corner_uvs; // per triangle corner, or empty
  std::vector<uint32_t> triangle_material;          // per triangle, or empty (material 0)
  std::vector<Material> materials;                  // at least one after import

  size_t face_count() const { return triangles.size(); }
  bool has_colours() const { return !colours.empty(); }
  bool has_uvs() const { return !corner_uvs.empty(); }
  uint32_t material_of(size_t triangle) const {
    return triangle_material.empty() ? 0 : triangle_material[triangle];
  }
};

// Hard limits on what we accept from outside; a larger file is refused, not attempted.
inline constexpr size_t kMaxMeshTriangles = 20'000'000;
inline constexpr size_t kMaxMeshVertices = 20'000'000;

// A triangle's one colour (SPEC C7): the mean of its vertex colours times its material colour.
glm::vec4 flat_colour(const Mesh& mesh, size_t triangle);

// Throws inkwire::Error with a one-line reason when the mesh cannot be rendered safely:
// no triangles, non-finite positions, indices out of range, attribute arrays of the wrong size.
void validate_mesh(const Mesh& mesh);

// Drops triangles that repeat a vertex (zero area by construction) and positions that no
// triangle uses, renumbering indices. Returns how many triangles were dropped.
size_t remove_degenerate_and_unused(Mesh& mesh);

// Moves the bounding-box centre to the origin and scales so the box diagonal is `diagonal`.
void normalise(Mesh& mesh, float diagonal = 1.0f);

}  // namespace inkwire
