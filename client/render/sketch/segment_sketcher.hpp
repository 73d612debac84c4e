#pragma once
// "sketch-segments" (SPEC S4): the object-segmentation sketcher. Uncertainty is applied once,
// at load time: for each of a few edge-length bins, a set of perturbed lines of unit length is
// made (with wiggle scaled so short and long edges wobble alike per unit of length). Each
// frame, every drawn edge picks one line of its bin by a pseudo-random index that changes with
// time, and the GPU draws it through the edge's transform (one draw per bin, the vertex shader
// pulling edge and line from buffers). No perturbation work per frame, so frame time stays
// constant and nothing stalls when the randomisation changes.
#include <array>
#include <memory>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"
#include "client/render/sketch/ink_lines.hpp"
#include "client/render/sketch/perturb.hpp"
#include "client/render/sketch/sketch_edges.hpp"

namespace inkwire {

// Unit sketchy lines for `bins` length bins: bin b holds `lines` polylines of `points(b)`
// points each, x running about 0..1 along and y across, in units of the edge's length.
struct UnitLines {
  std::vector<float> bin_upper;   // edge length (mesh units) below which an edge is in bin b
  std::vector<int> points;        // points per line in bin b
  std::vector<int> first;         // index of bin b's first point
  std::vector<glm::vec2> data;    // all points, bin by bin, line by line
  int lines = 0;
  int bin_of(float length) const;
};

UnitLines make_unit_lines(float diagonal, const PerturbOptions& options, int lines = 8, uint64_t seed = 3);

class SegmentSketcher final : public Renderer {
 public:
  SegmentSketcher();
  static std::vector<ParamSpec> params();
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  gl::Program program_;
  HiddenLineRemoval hlr_;
  SketchEdgeSource edges_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  UnitLines unit_lines_;
  gl::Texture unit_texture_, edge_texture_;  // read by segments.vert (common/data_texture.glsl)
  gl::VertexArray vao_;

  struct EdgeTransform {  // three texels of segments.vert's edges
    glm::vec4 start_and_opacity, end_and_line, side;
  };
  std::vector<std::vector<EdgeTransform>> by_bin_;
  std::vector<glm::vec4> packed_;

  InkLineStyle ink_;
  float depth_bias_ = 0.002f;
};

}  // namespace inkwire
