#pragma once
// Level of detail (SPEC G4) through meshoptimizer: simplify a mesh to about a requested number
// of triangles, keeping attributes of surviving vertices.
#include <vector>

#include "common/mesh.hpp"
#include "common/topology.hpp"

namespace inkwire {

// Returns a simplified copy with as close to `target_faces` triangles as the simplifier reaches
// (never more than the input). Texture coordinates and materials are carried per surviving
// triangle corner where the corner's vertex survives unchanged. `error`, when given, receives
// the simplifier's estimate of how far the surface moved, in the mesh's own units.
// With `exact` false the simplifier runs once and may stop short of the target.
Mesh simplify_to_faces(const Mesh& mesh, size_t target_faces, float* error = nullptr, bool exact = true);

// A mesh and its coarser copies, each with its topology and how far its surface strays from
// the full mesh (in the mesh's units). Outline finders pick, per frame, the coarsest level
// whose error projects to under a fraction of a pixel: the same outline on screen from far
// fewer edges when the object is small, the full mesh when it is close.
struct MeshLevel {
  Mesh mesh;
  Topology topology;
  float error = 0.0f;
};

class MeshLevels {
 public:
  // Level 0 is the mesh itself; each further level halves the face count, down to about
  // `min_faces`.
  MeshLevels(const Mesh& mesh, const Topology& topology, size_t min_faces = 400);
  // The coarsest level whose error, at `pixels_per_unit`, is at most `max_error_pixels`.
  size_t pick_index(float pixels_per_unit, float max_error_pixels) const;
  const MeshLevel& pick(float pixels_per_unit, float max_error_pixels) const {
    return levels_[pick_index(pixels_per_unit, max_error_pixels)];
  }
  size_t size() const { return levels_.size(); }
  const MeshLevel& operator[](size_t i) const { return levels_[i]; }

 private:
  std::vector<MeshLevel> levels_;
};

}  // namespace inkwire
