#pragma once
// Importance functions (SPEC S1): which edges a sketch may draw, decided once per mesh (static)
// and per frame (dynamic, see sketch_edges.hpp).
//
// Static: inface edges are already gone (Topology); an edge is dropped only when it is both
// short (MinLength) and nearly flat (MaxAngle): the two tests remove complementary detail
// (short creases and long flat edges both stay). User-flagged edges are always kept.
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

#include "common/topology.hpp"

namespace inkwire {

struct ImportanceOptions {
  float min_length = 0.0f;  // in the mesh's units
  float max_angle = 0.0f;   // dihedral angle, radians
};

// The S1 rule for one edge.
inline bool statically_important(const Edge& e, const ImportanceOptions& o) {
  return !(e.length < o.min_length && e.dihedral < o.max_angle);
}

// Indices into topology.edges of the edges a sketch may draw: the statically important ones
// plus every flagged one.
std::vector<uint32_t> important_edges(const Topology& topology, const ImportanceOptions& options,
                                      const std::vector<uint32_t>& flagged = {});

// Reads a file of vertex-index pairs ("a b" per line, '#' comments) naming edges the user
// wants drawn, and returns their indices into topology.edges. Throws inkwire::Error naming
// the line when a pair is malformed, out of range or not an edge of the mesh.
std::vector<uint32_t> load_flagged_edges(const std::filesystem::path& file, const Topology& topology, size_t vertex_count);

}  // namespace inkwire
