#include "client/render/sketch/sketch_edges.hpp"

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

namespace inkwire {
namespace {

const std::vector<uint8_t> kNoValleys;
constexpr float kWidestValleyRadians = 1.5707964f;

}  // namespace

bool is_closed_oriented_surface(const Mesh& mesh) {
  // Every directed edge a -> b of a triangle is matched by a b -> a of another: no holes, and
  // where more than two triangles meet at an edge they still pair up front to back.
  std::vector<uint64_t> forward, backward;
  forward.reserve(mesh.triangles.size() * 3);
  backward.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = t[size_t(k)], b = t[size_t((k + 1) % 3)];
      forward.push_back(a << 32 | b);
      backward.push_back(b << 32 | a);
    }
  std::sort(forward.begin(), forward.end());
  std::sort(backward.begin(), backward.end());
  return forward == backward;
}

std::vector<uint8_t> valley_edges_of_closed_mesh(const Mesh& mesh, const Topology& topology) {
  if (!is_closed_oriented_surface(mesh)) return {};
  std::vector<uint8_t> valleys(topology.edges.size(), 0);
  for (size_t i = 0; i < topology.edges.size(); ++i) {
    const Edge& e = topology.edges[i];
    // Which two faces make the valley is not clear at a non-manifold edge. Faces folded nearly
    // flat onto each other are where real meshes turn inside out locally (a fold-over), and
    // there a "valley" can face the viewer: only valleys opening wider than a right angle count.
    if (e.non_manifold || e.dihedral > kWidestValleyRadians) continue;
    uint32_t far = 0;
    for (uint32_t v : mesh.triangles[e.f1])
      if (v != e.v0 && v != e.v1) far = v;
    valleys[i] = glm::dot(topology.face_normals[e.f0], mesh.positions[far] - mesh.positions[e.v0]) > 0.0f;
  }
  return valleys;
}

void choose_sketch_edges(const Mesh& mesh, const Topology& topology, const std::vector<uint32_t>& candidates,
                         const glm::vec3& eye, float crease_radians, const FadeOptions& fade, std::vector<DrawnEdge>& out,
                         const std::vector<uint8_t>& valleys) {
  out.clear();
  for (uint32_t i : candidates) {
    const Edge& e = topology.edges[i];
    if (e.boundary) {
      out.push_back({i, 1.0f});
      continue;
    }
    // Which side of each face's plane the eye is on needs no unit vector; only fading does.
    const glm::vec3 to_eye = eye - 0.5f * (mesh.positions[e.v0] + mesh.positions[e.v1]);
    const float d1 = glm::dot(topology.face_normals[e.f0], to_eye);
    const float d2 = glm::dot(topology.face_normals[e.f1], to_eye);
    const bool silhouette = d1 * d2 < 0.0f;
    if (silhouette && !valleys.empty() && valleys[i]) continue;
    if (silhouette || (e.dihedral > crease_radians && (d1 > 0.0f || d2 > 0.0f))) {
      out.push_back({i, 1.0f});
      continue;
    }
    if (!fade.enabled) continue;
    const float to_unit = 1.0f / glm::length(to_eye);
    const float opacity = fade_opacity(d1 * to_unit, d2 * to_unit, fade);
    if (opacity > 0.0f) out.push_back({i, opacity});
  }
}

std::vector<ParamSpec> SketchEdgeSource::params(bool fade_by_default) {
  return {
      float_param("min_length", "0.01", 0, 1, "importance: edges shorter than this fraction of the bounding-box diagonal..."),
      float_param("max_angle", "12", 0, 180, "importance: ...and flatter than this many degrees are never drawn"),
      file_param("flagged_edges", "", "file of vertex-index pairs: edges always drawn"),
      float_param("crease_degrees", "50", 0, 180, "draw creases sharper than this"),
      bool_param("fade", fade_by_default ? "true" : "false", "fade edges in and out near the silhouette instead of popping"),
      float_param("fade_degrees", "5", 0.1, 45, "fading range"),
  };
}

void SketchEdgeSource::configure(const StyleParams& p) {
  min_length_ratio_ = p.get_float("min_length");
  max_angle_ = glm::radians(p.get_float("max_angle"));
  flagged_file_ = p.get_text("flagged_edges");
  crease_radians_ = glm::radians(p.get_float("crease_degrees"));
  fade_ = {p.get_bool("fade"), p.get_float("fade_degrees")};
  if (object_) prepare(*object_);  // thresholds depend on the object's size
}

void SketchEdgeSource::prepare(const SceneObject& object) {
  object_ = &object;
  const ImportanceOptions importance{min_length_ratio_ * object.topology.bounds.diagonal(), max_angle_};
  const std::vector<uint32_t> flagged =
      flagged_file_.empty() ? std::vector<uint32_t>{} : load_flagged_edges(flagged_file_, object.topology, object.mesh.positions.size());
  candidates_ = important_edges(object.topology, importance, flagged);
  valleys_ = valley_edges_of_closed_mesh(object.mesh, object.topology);
}

std::map<std::string, double> SketchEdgeSource::counters() const {
  if (!object_) return {};
  return {{"edges_total", double(object_->topology.edges.size())},
          {"edges_candidates", double(candidates_.size())},
          {"edges_drawn", double(drawn_.size())}};
}

const std::vector<DrawnEdge>& SketchEdgeSource::choose(const glm::vec3& eye) {
  // Valleys are hidden only to an eye outside the solid; outside the bounds it surely is.
  const Bounds& b = object_->topology.bounds;
  const bool outside = glm::any(glm::lessThan(eye, b.min)) || glm::any(glm::greaterThan(eye, b.max));
  choose_sketch_edges(object_->mesh, object_->topology, candidates_, eye, crease_radians_, fade_, drawn_,
                      outside ? valleys_ : kNoValleys);
  return drawn_;
}

}  // namespace inkwire
