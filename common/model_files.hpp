#pragma once
// Which files a model may read besides itself (its .bin, .mtl, textures). Normally any file its
// references name. A process importing a model someone uploaded (inkwire-import-model) confines
// every import to the upload's own folder first: assimp's file system and the texture lookups
// then refuse anything outside it, so a glTF whose buffer is "../../etc/passwd" or an OBJ whose
// texture is "/root/.ssh/id_rsa" reads nothing of the machine.
#include <filesystem>
#include <string>

#include <assimp/DefaultIOSystem.h>

namespace inkwire {

// From now on, in this process, model files are read only from under `folder`.
void confine_model_files(const std::filesystem::path& folder);
// Whether `file` may be read (always, unless confined). Throws nothing.
bool model_file_allowed(const std::filesystem::path& file);
// The first file a model asked for and was refused, since confining (empty: none).
std::string refused_model_file();

// assimp's own file system with that rule: every importer of common/ uses it.
class ModelIOSystem : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode) override;
};

}  // namespace inkwire
