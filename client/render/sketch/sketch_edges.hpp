#pragma once
// Per-frame edge choice for the sketch renderers (SPEC S1 dynamic importance, S6 fading).
//
// With d1, d2 the cosines between the two faces' normals and the direction to the viewer, an
// edge with d1 * d2 < 0 is on the silhouette. Edge fading maps d1 * d2 through a lookup that
// is 1 for negative values and falls to 0 over a small positive range, so edges fade in and
// out as the object turns instead of popping. The lookup is indexed by d1 * d2 divided by the
// larger of |d1|, |d2| (that is the smaller one: the sine of the nearer face's angle to edge-on),
// so "about 5 degrees" means the same for every edge, whatever its other face does.
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "client/render/scene_object.hpp"
#include "client/render/sketch/importance.hpp"
#include "common/mesh.hpp"
#include "common/style_params.hpp"
#include "common/topology.hpp"

namespace inkwire {

struct FadeOptions {
  bool enabled = false;
  float range_degrees = 5.0f;  // the nearer face this far past edge-on: fully faded out
};

// The S6 lookup. Without fading it is a step: 1 on the silhouette, 0 elsewhere.
inline float fade_opacity(float d1, float d2, const FadeOptions& fade) {
  if (d1 * d2 < 0.0f) return 1.0f;
  if (!fade.enabled) return 0.0f;
  const float nearer = std::min(std::abs(d1), std::abs(d2));
  const float range = std::sin(fade.range_degrees * 0.017453292f);
  return nearer >= range ? 0.0f : 1.0f - nearer / range;
}

struct DrawnEdge {
  uint32_t edge;  // index into topology.edges
  float opacity;  // 0..1
};

// True when every directed edge a -> b of a triangle is matched by a b -> a of another: a
// closed surface, oriented consistently, the boundary of a solid.
bool is_closed_oriented_surface(const Mesh& mesh);

// On a closed oriented surface seen from outside, a silhouette edge in a valley (concave: the
// far corner of one face lies above the other face's plane) is always hidden. Just before the
// sight line reaches it, it is behind the back-facing face's plane, which near a valley is
// inside the solid; so it entered the solid through a nearer front face, which the depth
// test finds. Per edge of `topology`: 1 for valleys (manifold edges whose faces turn by less
// than a right angle: sharper folds are where real meshes turn inside out); empty when the
// mesh is not such a surface, where the argument fails.
std::vector<uint8_t> valley_edges_of_closed_mesh(const Mesh& mesh, const Topology& topology);

// From the candidate edges (importance.hpp), those drawn this frame: silhouettes (faded when
// fading is on), open edges, and creases sharper than `crease_radians` with a face toward
// the viewer. `eye` is in the mesh's own coordinates. Silhouettes on `valleys` (see
// valley_edges_of_closed_mesh; may be empty) are left out: a hidden line costs as much to
// draw as a visible one, and a wobbling one pokes out from behind its occluder.
void choose_sketch_edges(const Mesh& mesh, const Topology& topology, const std::vector<uint32_t>& candidates,
                         const glm::vec3& eye, float crease_radians, const FadeOptions& fade, std::vector<DrawnEdge>& out,
                         const std::vector<uint8_t>& valleys = {});

// What every sketcher shares: the importance thresholds (relative to the object's size), the
// flagged-edges file, creases and fading, as style parameters, and the per-frame edge choice.
class SketchEdgeSource {
 public:
  static std::vector<ParamSpec> params(bool fade_by_default);
  void configure(const StyleParams& params);
  // Resolves thresholds for this object and picks its candidate edges (static importance).
  void prepare(const SceneObject& object);
  // The edges to draw for a viewer at `eye` (object space).
  const std::vector<DrawnEdge>& choose(const glm::vec3& eye);

  const std::vector<DrawnEdge>& drawn() const { return drawn_; }
  // edges_total, edges_candidates, edges_drawn: what every sketcher reports.
  std::map<std::string, double> counters() const;

 private:
  const SceneObject* object_ = nullptr;
  float min_length_ratio_ = 0.01f, max_angle_ = 0.2f, crease_radians_ = 0.9f;
  std::string flagged_file_;
  FadeOptions fade_;
  std::vector<uint32_t> candidates_;
  std::vector<uint8_t> valleys_;
  std::vector<DrawnEdge> drawn_;
};

}  // namespace inkwire
