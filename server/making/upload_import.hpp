#pragma once
// The model in an upload's folder (the files of a multipart body, multipart.hpp) made into the
// one GLB a scene serves (common/model_bundle.hpp), as a configured scene's model is, and checked
// as every client will read it (common/glb_mesh.hpp, the browser's reader) against the
// operator's limits. Run by inkwire-import-model, a process of its own under memory and time
// limits, with model files confined to the folder (common/model_files.hpp); here for tests and
// the fuzz target too.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace inkwire::server {

struct ImportLimits {
  uint64_t max_triangles = 2'000'000;
  uint64_t max_texture_pixels = 4096ull * 4096;
};

struct ImportedModel {
  std::string name;            // the model's own name, .glb
  std::vector<uint8_t> glb;
  uint64_t triangles = 0, texture_pixels = 0;
};

// The model file among `files` of an upload: the one a model reader opens (not a .bin, .mtl or
// picture it refers to). Throws inkwire::Error when there is none or more than one.
std::string upload_model_file(const std::vector<std::string>& files);

// Throws inkwire::Error with a one-line reason: no model, several, one no reader draws, over a limit.
ImportedModel import_upload(const std::filesystem::path& folder, const ImportLimits& limits);

}  // namespace inkwire::server
