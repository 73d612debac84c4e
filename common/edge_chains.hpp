#pragma once
// Joining outline edges into chains and simplifying them on screen.
//
// Silhouettes of real meshes zig-zag along many tiny edges (about a quarter of all edges of the
// 10 648-face bull at the benchmark pose). Drawn one by one, each costs a primitive; joined into
// chains through shared vertices and simplified in screen space (Douglas-Peucker) with a
// sub-pixel tolerance, the same outline needs several times fewer segments and loses its
// zig-zag. Sketch renderers reuse the chains as strokes.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace inkwire {

struct ChainEdge {
  uint32_t v0, v1;  // vertex indices
  uint32_t group;   // edges join only within a group (e.g. silhouette vs crease, line width)
};

struct Chain {
  std::vector<uint32_t> vertices;  // in order; a closed loop repeats its first vertex at the end
  std::vector<uint32_t> edges;     // edges[i] (index into the input) joins vertices[i], [i + 1]
  uint32_t group = 0;
};

// Joins edges into maximal chains through vertices shared by exactly two edges of one group
// (at branch points and ends a chain stops). Every edge ends up in exactly one chain.
// `vertex_count` bounds the vertex indices. Given `positions`, a chain also carries on through
// branch points, along the unused edge that turns least (if it turns less than
// `max_turn_degrees`): long strokes for sketching rather than the shortest pieces.
// Keep one builder for per-frame use: it reuses its storage, and the chains returned stay valid
// until the next build().
class ChainBuilder {
 public:
  std::span<const Chain> build(const std::vector<ChainEdge>& edges, size_t vertex_count,
                               const std::vector<glm::vec3>* positions = nullptr, float max_turn_degrees = 60.0f);

 private:
  std::vector<uint32_t> first_, next_;  // incidence lists: per vertex, per edge end
  std::vector<uint8_t> used_;
  std::vector<Chain> chains_;
  size_t chain_count_ = 0;
};

// Douglas-Peucker in screen space: keeps the chain's ends and every vertex farther than
// `tolerance` pixels from the simplified line. `screen` gives each vertex's position in
// pixels. Writes the positions within `chain` of the kept vertices to `out` (cleared first).
void simplify_chain(const std::vector<uint32_t>& chain, const std::vector<glm::vec2>& screen, float tolerance,
                    std::vector<uint32_t>& out);

}  // namespace inkwire
