#pragma once
// Loads a triangle mesh from any format assimp reads (SPEC G1: OBJ, PLY, OFF, 3DS, ASE, glTF and
// more), flattening the node hierarchy, triangulating polygons and welding equal positions so
// the topology is real. Bad files end in inkwire::Error with a one-line reason.
#include <filesystem>
#include <optional>
#include <string>

#include <glm/mat4x4.hpp>

#include "common/mesh.hpp"

namespace inkwire {

struct ImportReport {
  size_t source_vertices = 0;      // vertices in the file, before welding
  size_t degenerate_dropped = 0;   // triangles repeating a vertex after welding
  size_t non_triangles_skipped = 0;  // points and lines, which no renderer draws
};

// Files larger than this are refused before assimp sees them.
inline constexpr uintmax_t kMaxMeshFileBytes = 1ull << 30;

// Which of a model file's own axes points up. Inkwire's scenes are Y-up (as glTF says); a file
// modelled Z-up is turned to stand upright. Auto: what the file says (FBX's UpAxis), else its
// format's convention (3D Studio: Z, which assimp already turns; everything else: Y).
enum class UpAxis { Auto, Y, Z };
// "auto", "y" or "z"; throws inkwire::Error naming the accepted values.
UpAxis parse_up_axis(const std::string& text);
const char* to_string(UpAxis up);

Mesh load_mesh(const std::filesystem::path& file, ImportReport* report = nullptr, UpAxis up = UpAxis::Auto);

// The way up a file has by its own account (Auto resolved).
UpAxis file_up_axis(const std::filesystem::path& file);

// What turns the model as assimp reads `file` so that its axis `up` points along +Y.
glm::mat4 upright_transform(const std::filesystem::path& file, UpAxis up);

// The file a model's texture reference `ref` names (as written relative to the model, else by
// its name beside the model, in any letter case); none for embedded ("*0") or missing ones.
std::optional<std::filesystem::path> find_texture_file(const std::filesystem::path& model, const std::string& ref);

}  // namespace inkwire
