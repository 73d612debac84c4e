#include "client/render/scene_object.hpp"

#include "common/error.hpp"
#include "common/lod.hpp"
#include "common/mesh_import.hpp"

namespace inkwire {

SceneObject make_scene_object(Mesh mesh) {
  validate_mesh(mesh);
  SceneObject object;
  object.topology = build_topology(mesh);
  object.material_images.resize(mesh.materials.size());
  for (size_t m = 0; m < mesh.materials.size(); ++m) {
    const Material& mat = mesh.materials[m];
    try {
      if (!mat.texture_bytes.empty())
        object.material_images[m] = load_image_from_memory(mat.texture_bytes, mat.name.empty() ? "embedded texture" : mat.name);
      else if (!mat.texture_file.empty())
        object.material_images[m] = load_image(mat.texture_file);
    } catch (const Error& e) {
      // A broken texture should not cost the user the model: draw that material untextured.
      object.warnings.push_back(std::string("texture ignored: ") + e.what());
    }
  }
  object.mesh = std::move(mesh);
  return object;
}

#ifndef __EMSCRIPTEN__  // files through assimp: the browser's module reads GLB from memory (common/glb_mesh)
SceneObject load_scene_object(const std::filesystem::path& file, size_t lod_faces, float diagonal, UpAxis up) {
  Mesh mesh = load_mesh(file, nullptr, up);
  if (lod_faces > 0) mesh = simplify_to_faces(mesh, lod_faces);
  normalise(mesh, diagonal);
  return make_scene_object(std::move(mesh));
}
#endif

}  // namespace inkwire
