#pragma once
// Level of detail (SPEC G4) through meshoptimizer: simplify a mesh to about a requested number
// of triangles, keeping attributes of surviving vertices.
#include "common/mesh.hpp"

namespace inkwire {

// Returns a simplified copy with as close to `target_faces` triangles as the simplifier reaches
// (never more than the input). Texture coordinates and materials are carried per surviving
// triangle corner where the corner's vertex survives unchanged.
Mesh simplify_to_faces(const Mesh& mesh, size_t target_faces);

}  // namespace inkwire
