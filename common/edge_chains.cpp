#include "common/edge_chains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace inkwire {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

}  // namespace

std::span<const Chain> ChainBuilder::build(const std::vector<ChainEdge>& edges, size_t vertex_count,
                                           const std::vector<glm::vec3>* positions, float max_turn_degrees) {
  // Incidence lists as linked lists in flat arrays: first_[v] -> edge end e (edge e/2,
  // end e%2), next_[e] -> the next end at the same vertex.
  first_.assign(vertex_count, kNone);
  next_.assign(edges.size() * 2, kNone);
  used_.assign(edges.size(), 0);
  for (uint32_t e = 0; e < edges.size(); ++e) {
    const uint32_t ends[2] = {edges[e].v0, edges[e].v1};
    for (uint32_t side = 0; side < 2; ++side) {
      next_[2 * e + side] = first_[ends[side]];
      first_[ends[side]] = 2 * e + side;
    }
  }
  auto vertex_at = [&](uint32_t end) { return end % 2 ? edges[end / 2].v1 : edges[end / 2].v0; };
  const float min_cos = std::cos(max_turn_degrees * 0.017453292f);
  // Where the chain goes on from vertex v, arriving by `from_edge`: the other edge of `group`
  // if v joins exactly two; with positions, at a branch, the unused one that turns least.
  auto continuation = [&](uint32_t v, uint32_t group, uint32_t from_edge) {
    uint32_t found = kNone, count = 0;
    for (uint32_t end = first_[v]; end != kNone; end = next_[end]) {
      if (edges[end / 2].group != group) continue;
      ++count;
      if (end / 2 != from_edge) found = end;
    }
    if (count == 2) return found != kNone && !used_[found / 2] ? found : kNone;
    if (!positions || count < 2) return kNone;
    const ChainEdge& in = edges[from_edge];
    const glm::vec3 arriving = glm::normalize((*positions)[v] - (*positions)[in.v0 == v ? in.v1 : in.v0]);
    uint32_t best = kNone;
    float best_cos = min_cos;
    for (uint32_t end = first_[v]; end != kNone; end = next_[end]) {
      const ChainEdge& out = edges[end / 2];
      if (out.group != group || used_[end / 2] || end / 2 == from_edge) continue;
      const glm::vec3 leaving = glm::normalize((*positions)[out.v0 == v ? out.v1 : out.v0] - (*positions)[v]);
      const float c = glm::dot(arriving, leaving);
      if (c > best_cos) best_cos = c, best = end;
    }
    return best;
  };
  // Degree of v within a group: chains start where it is not 2.
  auto degree = [&](uint32_t v, uint32_t group) {
    uint32_t count = 0;
    for (uint32_t end = first_[v]; end != kNone; end = next_[end]) count += edges[end / 2].group == group;
    return count;
  };

  chain_count_ = 0;
  auto walk = [&](uint32_t start_edge, uint32_t start_end) {
    if (chain_count_ == chains_.size()) chains_.emplace_back();
    Chain& chain = chains_[chain_count_++];
    chain.group = edges[start_edge].group;
    chain.vertices.clear();
    chain.edges.clear();
    chain.vertices.push_back(vertex_at(start_end));
    uint32_t edge = start_edge, end = start_end;
    while (true) {
      used_[edge] = 1;
      chain.edges.push_back(edge);
      const uint32_t far_end = end ^ 1u;  // the edge's other end
      const uint32_t v = vertex_at(far_end);
      chain.vertices.push_back(v);
      const uint32_t next = continuation(v, chain.group, edge);
      if (next == kNone) break;
      edge = next / 2;
      end = next;
    }
  };
  // Open chains first, from their ends, so they are not cut in the middle; then loops.
  for (uint32_t e = 0; e < edges.size(); ++e)
    for (uint32_t side = 0; side < 2 && !used_[e]; ++side)
      if (degree(vertex_at(2 * e + side), edges[e].group) != 2) walk(e, 2 * e + side);
  for (uint32_t e = 0; e < edges.size(); ++e)
    if (!used_[e]) walk(e, 2 * e);
  return {chains_.data(), chain_count_};  // storage is reused across calls
}

void simplify_chain(const std::vector<uint32_t>& chain, const std::vector<glm::vec2>& screen, float tolerance,
                    std::vector<uint32_t>& out) {
  out.clear();
  if (chain.size() <= 2) {
    for (uint32_t i = 0; i < chain.size(); ++i) out.push_back(i);
    return;
  }
  const float tolerance2 = tolerance * tolerance;
  std::vector<uint8_t> keep(chain.size(), 0);
  keep.front() = keep.back() = 1;
  // Iterative Douglas-Peucker over index ranges.
  std::vector<std::pair<size_t, size_t>> stack = {{0, chain.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    const glm::vec2 pa = screen[chain[a]], pb = screen[chain[b]];
    const glm::vec2 d = pb - pa;
    const float length2 = glm::dot(d, d);
    float worst = -1.0f;
    size_t worst_at = a;
    for (size_t i = a + 1; i < b; ++i) {
      const glm::vec2 p = screen[chain[i]] - pa;
      // Squared distance to the segment (to the end point when the segment is degenerate,
      // as for a closed loop whose ends coincide).
      const float t = length2 > 0.0f ? std::clamp(glm::dot(p, d) / length2, 0.0f, 1.0f) : 0.0f;
      const glm::vec2 off = p - t * d;
      const float dist2 = glm::dot(off, off);
      if (dist2 > worst) worst = dist2, worst_at = i;
    }
    if (worst > tolerance2) {
      keep[worst_at] = 1;
      stack.push_back({a, worst_at});
      stack.push_back({worst_at, b});
    }
  }
  for (size_t i = 0; i < chain.size(); ++i)
    if (keep[i]) out.push_back(uint32_t(i));
}

}  // namespace inkwire
