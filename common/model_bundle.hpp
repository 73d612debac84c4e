#pragma once
// A model that is several files (glTF with its .bin and images, OBJ with its .mtl and images,
// anything assimp follows) made into one self-contained binary glTF (GLB) with its textures
// inside, so it travels as one asset and a client gets it whole.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/mesh_import.hpp"

namespace inkwire {

struct SelfContainedModel {
  std::string name;            // the model's name with .glb
  std::vector<uint8_t> bytes;  // the GLB
  std::vector<std::filesystem::path> gathered;  // the files folded into it besides the model itself
};

// None when `file` is a GLB that refers to no other file and whose up axis any reader finds by
// itself: it already travels whole. Otherwise a GLB turned Y-up (an OFF or PLY too, so every
// client, the browser's included, reads one format).
// Throws inkwire::Error with the path when the model cannot be read, a file it refers to is
// missing, or no GLB can be written from it.
std::optional<SelfContainedModel> self_contained_model(const std::filesystem::path& file, UpAxis up = UpAxis::Auto);

}  // namespace inkwire
