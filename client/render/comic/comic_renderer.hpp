#pragma once
// Comic renderers (SPEC C1-C9). "comic": a 1D shade map indexed by N.L, back-face culling by
// GL. "comic-extended": a 2D shade map indexed by (N.L, R.V) for a view-dependent highlight,
// and the study's fast orientation methods choosing the triangles to draw on the CPU.
// Both draw the outline as back faces in wide lines behind the filled front faces.
#include <memory>
#include <optional>
#include <vector>

#include "client/render/comic/shade_maps.hpp"
#include "client/render/gpu_mesh.hpp"
#include "client/render/renderer.hpp"
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
  // Fills dynamic_elements_ / drawn_slots_ with the triangles the orientation method keeps.
  void pick_triangles();
  void draw_fill(const FrameState& frame);
  void draw_outline(const FrameState& frame);
  void upload_shade_map();

  bool extended_;
  gl::Program fill_, outline_;
  const SceneObject* object_ = nullptr;
  std::unique_ptr<GpuMesh> mesh_;
  gl::Buffer triangle_colours_, drawn_slots_, dynamic_elements_;
  gl::VertexArray dynamic_vao_;
  std::optional<gl::Texture> shade_texture_;
  ShadeMap shade_map_;

  // Style.
  std::optional<Orientation> orientation_;  // empty: GL back-face culling
  int k_ = 1;
  bool use_vertex_margins_ = true;
  std::vector<float> vertex_margins_;
  float outline_width_ = 4.0f, outline_darkening_ = 0.6f, shadow_saturation_ = 0.12f;
  bool coloured_outline_ = false;
  glm::vec3 ink_{0.0f};

  // Per frame.
  std::vector<uint8_t> draw_flags_, vertex_scratch_;
  std::vector<uint32_t> picked_indices_, picked_slots_;
  struct Range {
    uint32_t first_triangle, triangles;
  };
  std::vector<Range> picked_ranges_;  // per GpuMesh batch
  size_t triangles_drawn_ = 0;
  glm::vec3 last_eye_{0.0f};
};

}  // namespace inkwire
