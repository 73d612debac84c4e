#include "common/lod.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>

#include <meshoptimizer.h>

#include "common/error.hpp"

namespace inkwire {
namespace {

std::vector<uint32_t> flat_indices(const Mesh& mesh) {
  std::vector<uint32_t> indices;
  indices.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  return indices;
}

std::vector<uint32_t> run_simplifier(const Mesh& mesh, const std::vector<uint32_t>& indices, size_t target_faces,
                                     float& relative_error) {
  std::vector<uint32_t> out(indices.size());
  // An error bound of 1 (the whole mesh extent) lets the face count, not the error, decide.
  const size_t n = meshopt_simplify(out.data(), indices.data(), indices.size(), &mesh.positions[0].x, mesh.positions.size(),
                                    sizeof(glm::vec3), target_faces * 3, 1.0f, 0, &relative_error);
  out.resize(n);
  return out;
}

}  // namespace

Mesh simplify_to_faces(const Mesh& mesh, size_t target_faces, float* error, bool exact) {
  validate_mesh(mesh);
  if (target_faces < 4) throw Error("cannot simplify to fewer than 4 triangles");
  if (error) *error = 0.0f;
  if (target_faces >= mesh.face_count()) return mesh;

  const std::vector<uint32_t> indices = flat_indices(mesh);
  // meshoptimizer stops at or below the target; nudge the request so the result lands as close
  // to the target as it can (the study's LOD series names exact face counts).
  std::vector<uint32_t> best;
  float best_error = 0.0f;
  size_t request = target_faces;
  for (int attempt = 0; attempt < (exact ? 8 : 1); ++attempt) {
    float relative_error = 0.0f;
    std::vector<uint32_t> got = run_simplifier(mesh, indices, request, relative_error);
    const size_t faces = got.size() / 3;
    if (best.empty() || std::labs(long(faces) - long(target_faces)) < std::labs(long(best.size() / 3) - long(target_faces))) {
      best = std::move(got);
      best_error = relative_error;
    }
    if (faces == target_faces) break;
    request = faces < target_faces ? request + (target_faces - faces) : request - std::min(request - 4, faces - target_faces);
    if (request >= mesh.face_count()) break;
  }
  if (best.empty()) throw Error("simplification removed every triangle");
  if (error) *error = best_error * meshopt_simplifyScale(&mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3));

  // Keep per-triangle attributes: find each surviving triangle's source by its vertex set.
  std::map<std::array<uint32_t, 3>, size_t> source_of;
  auto sorted = [](std::array<uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  for (size_t t = 0; t < mesh.triangles.size(); ++t) source_of.emplace(sorted(mesh.triangles[t]), t);

  // A surviving triangle takes each corner's UV from the source triangle with the same vertices,
  // or, when the simplifier made a new triangle, from any source corner at that vertex.
  std::vector<glm::vec2> uv_of_vertex(mesh.has_uvs() ? mesh.positions.size() : 0, glm::vec2(0.0f));
  for (size_t t = 0; t < mesh.corner_uvs.size(); ++t)
    for (int c = 0; c < 3; ++c) uv_of_vertex[mesh.triangles[t][c]] = mesh.corner_uvs[t][c];

  Mesh out;
  out.positions = mesh.positions;
  out.colours = mesh.colours;
  out.materials = mesh.materials;
  for (size_t i = 0; i < best.size(); i += 3) {
    const std::array<uint32_t, 3> tri{best[i], best[i + 1], best[i + 2]};
    const auto found = source_of.find(sorted(tri));
    const bool has_source = found != source_of.end();
    out.triangles.push_back(tri);
    if (!mesh.triangle_material.empty()) out.triangle_material.push_back(mesh.material_of(has_source ? found->second : 0));
    if (!mesh.has_uvs()) continue;
    std::array<glm::vec2, 3> uv{};
    for (int c = 0; c < 3; ++c) {
      uv[c] = uv_of_vertex[tri[c]];
      if (!has_source) continue;
      for (int s = 0; s < 3; ++s)
        if (mesh.triangles[found->second][s] == tri[c]) uv[c] = mesh.corner_uvs[found->second][s];
    }
    out.corner_uvs.push_back(uv);
  }
  remove_degenerate_and_unused(out);
  validate_mesh(out);
  return out;
}

MeshLevels::MeshLevels(const Mesh& mesh, const Topology& topology, size_t min_faces) {
  levels_.push_back({mesh, topology, 0.0f});
  for (size_t faces = mesh.face_count() / 2; faces >= min_faces; faces /= 2) {
    MeshLevel level;
    // Always from the full mesh, so each level's error is measured against it.
    level.mesh = simplify_to_faces(mesh, faces, &level.error, false);
    if (level.mesh.face_count() >= levels_.back().mesh.face_count()) break;  // the simplifier is stuck
    level.topology = build_topology(level.mesh);
    levels_.push_back(std::move(level));
  }
}

size_t MeshLevels::pick_index(float pixels_per_unit, float max_error_pixels) const {
  size_t chosen = 0;
  for (size_t i = 1; i < levels_.size(); ++i)
    if (levels_[i].error * pixels_per_unit <= max_error_pixels) chosen = i;
  return chosen;
}

}  // namespace inkwire
