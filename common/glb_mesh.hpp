#pragma once
// Reads a binary glTF (GLB) held in memory into a Mesh without assimp: the reader the browser's
// module uses for the session's model (the server sends every mesh as one self-contained GLB).
// It follows what the native reader (assimp, common/mesh_import) makes of the same file: nodes in
// order with their transforms, triangles (lists, strips, fans), COLOR_0, TEXCOORD_0 (v turned as
// assimp turns it), base colour and embedded base-colour texture, equal positions welded.
#include <cstdint>
#include <span>
#include <string>

#include "common/mesh.hpp"

namespace inkwire {

// Throws inkwire::Error with a one-line reason naming `name` when the bytes are not a GLB this
// reader can draw: malformed, external buffers or images, accessors out of range, no triangles.
Mesh read_glb_mesh(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace inkwire
