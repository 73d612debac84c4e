#pragma once
// What a client holds for one mesh: the mesh, its topology (built once, SPEC G2) and the decoded
// texture image of each material (empty when a material has none or its file was unusable).
#include <string>
#include <vector>

#include "common/image.hpp"
#include "common/mesh.hpp"
#include "common/mesh_import.hpp"
#include "common/topology.hpp"

namespace inkwire {

struct SceneObject {
  Mesh mesh;
  Topology topology;
  std::vector<Image> material_images;
  std::vector<std::string> warnings;  // e.g. a texture that could not be read: drawn untextured
};

SceneObject make_scene_object(Mesh mesh);

// Loads a mesh file, simplifies it to about `lod_faces` triangles when non-zero, centres it and
// scales its bounding-box diagonal to `diagonal`. Throws inkwire::Error with a one-line reason.
SceneObject load_scene_object(const std::filesystem::path& file, size_t lod_faces = 0, float diagonal = 10.0f, UpAxis up = UpAxis::Auto);

}  // namespace inkwire
