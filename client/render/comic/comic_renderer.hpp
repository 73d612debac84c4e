#pragma once
// Comic renderers (SPEC C1-C9). "comic": a 1D shade map indexed by N.L. "comic-extended": a
// 2D shade map indexed by (N.L, R.V) for a view-dependent highlight, and the study's fast
// orientation methods choosing on the CPU which triangles to submit.
//
// Outlines: "edges" (default) draws the silhouette (exact per-face test) and visible creases
// as wide lines, creases at half width; "backfaces" is the study's method, every back face
// as a wide line behind the fill, which costs several times more on a software rasteriser.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "client/render/comic/shade_maps.hpp"
#include "client/render/gpu_mesh.hpp"
#include "client/render/renderer.hpp"
#include "client/render/wide_lines.hpp"
#include "common/edge_chains.hpp"
#include "common/lod.hpp"
#include "common/orientation.hpp"

namespace inkwire {

class ComicRenderer final : public Renderer {
 public:
  explicit ComicRenderer(bool extended);
  static std::vector<ParamSpec> params(bool extended);
  void configure(const StyleParams& params) override;
  void prepare(const SceneObject& object) override;
  void draw(const FrameState& frame) override;
  std::map<std::string, double> counters() const override;

 private:
  void pick_triangles();  // fills dynamic_elements_ with what the orientation method keeps
  void draw_fill(const FrameState& frame);
  void draw_backface_outline(const FrameState& frame);
  void draw_edge_outline(const FrameState& frame);
  void upload_shade_map();

  bool extended_;
  // Fill programs without and with the base texture: a uniform branch around the texture read
  // still costs every fragment the read under llvmpipe, so untextured batches get their own.
  std::array<gl::Program, 2> fill_;
  gl::Program backface_outline_, edge_outline_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  gl::Buffer dynamic_elements_, edge_vertices_, backface_edges_;
  gl::VertexArray dynamic_vao_, edge_vao_, backface_vao_;
  size_t backface_edge_vertices_ = 0;
  std::optional<gl::Texture> shade_texture_;
  ShadeMap shade_map_;
  VertexMargins vertex_margins_;
  std::unique_ptr<MeshLevels> outline_levels_;            // silhouettes come from these
  std::vector<std::vector<glm::vec4>> level_face_colours_;  // per level, per face (C8)

  // Style.
  std::optional<Orientation> orientation_;  // empty: submit everything, GL culls
  int k_ = 1;
  bool use_vertex_margins_ = true, backface_outline_mode_ = false, coloured_outline_ = false;
  float outline_width_ = 4.0f, outline_darkening_ = 0.6f, shadow_saturation_ = 0.12f, crease_radians_ = 1.05f;
  float outline_tolerance_ = 0.5f, outline_min_length_ = 2.0f, outline_error_ = 0.5f;
  glm::vec3 ink_{0.0f};

  // Per frame.
  std::vector<uint8_t> draw_flags_, vertex_scratch_, exact_front_;
  std::vector<uint32_t> picked_indices_;
  struct Range {
    uint32_t first_triangle, triangles;
  };
  std::vector<Range> picked_ranges_;  // per GpuMesh batch
  struct LineVertex {  // a corner of a wide line (attributes 0-3) and its colour (4)
    WideLineVertex line;
    glm::vec3 colour;
  };
  struct BackfaceEdgeVertex {  // a corner of a wide line and the two faces beside its edge
    WideLineVertex line;
    glm::vec3 normal_a, normal_b;
    glm::vec4 colour_a, colour_b;
  };
  std::vector<LineVertex> line_vertices_[2];  // silhouettes (full width), creases (half)
  std::vector<ChainEdge> outline_edges_;
  std::vector<uint32_t> outline_faces_;  // the face whose colour each outline edge takes
  ChainBuilder chains_;
  std::vector<glm::vec2> screen_;
  std::vector<uint32_t> kept_;
  size_t edges_drawn_ = 0, segments_drawn_ = 0, outline_level_faces_ = 0;
  size_t triangles_drawn_ = 0;
  ViewSetup view_{};  // this frame's viewer, in object space
};

}  // namespace inkwire
