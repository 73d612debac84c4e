#pragma once
// "sketch-recursive" (SPEC S3): silhouettes, open edges and creases found by an exhaustive
// search, joined into strokes (chains of edges, at most a set length), each stroke drawn 1-4
// times as a recursively perturbed line (S2), over paper with hidden lines removed (G6, G7).
// Perturbing whole strokes rather than single mesh edges matters on dense meshes: an edge is a
// hundredth of the object, and a wobble proportional to it is invisible.
//
// Boiling: the randomisation changes every 1/boil_hz seconds of animation time (12 Hz looks
// most natural). A handful of randomisations ("sets") are kept on the GPU and replayed in a
// shuffled order, so a still view costs no perturbation work at all; under rotation the edge
// set is found again only every few frames (the error hides in the deliberate wobble) and the
// sets are rebuilt then. Each edge's wobble depends only on the edge and the set, so an edge
// looks the same while it stays in view.
#include <array>
#include <memory>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"
#include "client/render/wide_lines.hpp"
#include "client/render/sketch/importance.hpp"
#include "client/render/sketch/ink_lines.hpp"
#include "client/render/sketch/perturb.hpp"
#include "client/render/sketch/sketch_edges.hpp"
#include "common/edge_chains.hpp"

namespace inkwire {

class RecursiveSketcher final : public Renderer {
 public:
  RecursiveSketcher();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

  static constexpr int kSets = 4;

 private:
  void build_set(int set, const FrameState& frame);
  int repetitions() const;

  gl::Program strokes_;
  HiddenLineRemoval hlr_;
  SketchEdgeSource edges_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;

  struct StrokeSet {
    gl::Buffer buffer;
    gl::VertexArray vao;
    size_t vertices = 0;
    long generation = -1;  // which edge search it was built for
  };
  std::array<StrokeSet, kSets> sets_;
  std::vector<ChainEdge> chain_edges_;
  ChainBuilder chains_;
  std::vector<WideLineVertex> scratch_;
  struct Stroke {
    uint64_t id;    // seeds its wobble: the first edge's index, stable while it stays drawn
    float opacity;
    std::vector<uint32_t> vertices;
  };
  std::vector<Stroke> strokes_found_;
  std::vector<glm::vec3> stroke_points_, stroke_sides_, polyline_;
  size_t stroke_count_ = 0;
  long generation_ = 0, frames_since_search_ = 1 << 30;  // first frame always searches

  // Style.
  InkLineStyle ink_;
  PerturbOptions perturb_;  // ink_ resolved for the object's size
  float depth_bias_ = 0.002f;
  int max_repetitions_ = 3, stroke_budget_ = 1500, search_every_ = 3;
  // Relative to the bounding-box diagonal, resolved at prepare().
  float max_stroke_ratio_ = 0.3f, max_stroke_ = 1.0f, min_stroke_ratio_ = 0.03f, min_stroke_ = 0.0f;
};

}  // namespace inkwire
