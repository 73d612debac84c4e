#pragma once
// "sketch-pencil", "sketch-charcoal", "sketch-chalk" (SPEC S5, S6): every drawn edge becomes a
// quad widened across both the edge and the view (cross(E, V)), its width proportional to the
// edge's length but clamped, textured with one of a medium's stroke textures chosen at random
// once per edge and kept for life; texture coordinates repeat by a measure of the object's size
// precomputed per edge, so marks keep their scale on any mesh. Depth test on, depth writes
// off, so strokes meeting at a vertex overlap as a hand's would. Edges fade in and out near the
// silhouette (S6), on by default. Charcoal also presses unevenly (width and darkness change
// smoothly along the outline), catches the paper's tooth and leaves a rubbed tone along the
// outline on the shadow side; any medium can be asked for these (pressure, grain, smudge).
#include <memory>
#include <vector>

#include "client/render/gpu_mesh.hpp"
#include "client/render/hidden_lines.hpp"
#include "client/render/renderer.hpp"
#include "client/render/sketch/sketch_edges.hpp"
#include "client/render/sketch/stroke_textures.hpp"

namespace inkwire {

class TexturedSketcher final : public Renderer {
 public:
  explicit TexturedSketcher(Medium medium);
  static std::vector<ParamSpec> params(Medium medium);
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  Medium medium_;
  gl::Program program_, smudge_program_;
  std::unique_ptr<gl::Texture> tooth_;  // the paper's grain, for dry media and the smudge
  std::vector<float> pressures_;        // per mesh vertex, 0..1
  HiddenLineRemoval hlr_;
  SketchEdgeSource edges_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  std::unique_ptr<gl::Texture> textures_;
  gl::Buffer vertices_, quad_indices_;
  gl::VertexArray vao_;

  // Per edge, for life: texture variant, where along the texture it starts, how often it
  // repeats along the edge.
  struct EdgeLook {
    float variant, u_start, u_repeat;
  };
  std::vector<EdgeLook> looks_;

  struct Vertex {
    glm::vec3 position;
    glm::vec3 coord;  // u, v, variant
    float opacity;
    glm::vec2 run;    // distance from the quad's start and its whole length, in half-widths
    float pressure;
  };
  std::vector<Vertex> quads_;

  // Style.
  int variants_ = 4;
  float width_ratio_ = 0.15f, min_width_ratio_ = 0.004f, max_width_ratio_ = 0.012f, texture_length_ratio_ = 0.08f;
  float strength_ = 1.0f, depth_bias_ = 0.002f;
  float pressure_ = 0.0f, grain_ = 0.0f, smudge_ = 0.0f;
  float min_width_ = 0.0f, max_width_ = 0.0f;
};

}  // namespace inkwire
