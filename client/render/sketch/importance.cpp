#include "client/render/sketch/importance.hpp"

#include <fstream>
#include <sstream>
#include <unordered_map>

#include "common/error.hpp"

namespace inkwire {

std::vector<uint32_t> important_edges(const Topology& topology, const ImportanceOptions& options,
                                      const std::vector<uint32_t>& flagged) {
  std::vector<uint8_t> keep(topology.edges.size(), 0);
  for (size_t i = 0; i < topology.edges.size(); ++i) keep[i] = statically_important(topology.edges[i], options);
  for (uint32_t i : flagged) keep.at(i) = 1;
  std::vector<uint32_t> kept;
  for (uint32_t i = 0; i < keep.size(); ++i)
    if (keep[i]) kept.push_back(i);
  return kept;
}

std::vector<uint32_t> load_flagged_edges(const std::filesystem::path& file, const Topology& topology, size_t vertex_count) {
  std::ifstream in(file);
  if (!in) throw Error(file.string() + ": cannot open");
  std::unordered_map<uint64_t, uint32_t> edge_of;
  for (uint32_t i = 0; i < topology.edges.size(); ++i)
    edge_of[uint64_t(topology.edges[i].v0) << 32 | topology.edges[i].v1] = i;
  std::vector<uint32_t> flagged;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    long long a = 0, b = 0;
    std::string extra;
    if (!(words >> a)) continue;  // blank or comment
    const std::string where = file.string() + ":" + std::to_string(number) + ": ";
    if (!(words >> b) || (words >> extra)) throw Error(where + "expected two vertex indices");
    if (a < 0 || b < 0 || size_t(a) >= vertex_count || size_t(b) >= vertex_count)
      throw Error(where + "vertex index out of range (the mesh has " + std::to_string(vertex_count) + ")");
    const uint64_t key = uint64_t(std::min(a, b)) << 32 | uint64_t(std::max(a, b));
    const auto found = edge_of.find(key);
    if (found == edge_of.end()) throw Error(where + "vertices " + std::to_string(a) + " and " + std::to_string(b) + " are not joined by a drawable edge");
    flagged.push_back(found->second);
  }
  return flagged;
}

}  // namespace inkwire
