#include "client/render/sketch/sketch_edges.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace inkwire {

void choose_sketch_edges(const Mesh& mesh, const Topology& topology, const std::vector<uint32_t>& candidates,
                         const glm::vec3& eye, float crease_radians, const FadeOptions& fade, std::vector<DrawnEdge>& out) {
  out.clear();
  for (uint32_t i : candidates) {
    const Edge& e = topology.edges[i];
    const glm::vec3 mid = 0.5f * (mesh.positions[e.v0] + mesh.positions[e.v1]);
    const glm::vec3 to_eye = glm::normalize(eye - mid);
    const float d1 = glm::dot(topology.face_normals[e.f0], to_eye);
    if (e.boundary) {
      out.push_back({i, 1.0f});
      continue;
    }
    const float d2 = glm::dot(topology.face_normals[e.f1], to_eye);
    if (e.dihedral > crease_radians && (d1 > 0.0f || d2 > 0.0f)) {
      out.push_back({i, 1.0f});
      continue;
    }
    const float opacity = fade_opacity(d1, d2, fade);
    if (opacity > 0.0f) out.push_back({i, opacity});
  }
}

std::vector<ParamSpec> SketchEdgeSource::params(bool fade_by_default) {
  return {
      float_param("min_length", "0.01", 0, 1, "importance: edges shorter than this fraction of the bounding-box diagonal..."),
      float_param("max_angle", "12", 0, 180, "importance: ...and flatter than this many degrees are never drawn"),
      text_param("flagged_edges", "", "file of vertex-index pairs: edges always drawn"),
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
}

std::map<std::string, double> SketchEdgeSource::counters() const {
  if (!object_) return {};
  return {{"edges_total", double(object_->topology.edges.size())},
          {"edges_candidates", double(candidates_.size())},
          {"edges_drawn", double(drawn_.size())}};
}

const std::vector<DrawnEdge>& SketchEdgeSource::choose(const glm::vec3& eye) {
  choose_sketch_edges(object_->mesh, object_->topology, candidates_, eye, crease_radians_, fade_, drawn_);
  return drawn_;
}

}  // namespace inkwire
