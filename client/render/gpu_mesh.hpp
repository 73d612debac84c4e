#pragma once
// A scene object's geometry uploaded once (SPEC G5): one interleaved vertex buffer, one index
// buffer, and one draw batch per material, triangles sorted by material at load time so a frame
// switches state once per material rather than per face.
#include <vector>

#include <glm/vec4.hpp>

#include "client/gl/resources.hpp"
#include "client/render/scene_object.hpp"

namespace inkwire {

struct GpuVertex {
  glm::vec3 position;
  glm::vec3 normal;       // vertex normal (average of adjacent face normals)
  glm::vec4 colour;       // vertex colour x material base colour, for smooth shading
  glm::vec4 flat_colour;  // the triangle's one colour (mean of its vertex colours x material
                          // colour) for `flat` shading, SPEC C7: any corner can be provoking.
                          // Corners weld only where their triangles' colours agree.
  glm::vec2 uv;
};

struct GpuBatch {
  uint32_t first_index = 0;
  uint32_t index_count = 0;
  uint32_t material = 0;
  bool textured = false;
};

class GpuMesh {
 public:
  explicit GpuMesh(const SceneObject& object);

  // Attribute locations every mesh shader uses.
  static constexpr GLuint kPosition = 0, kNormal = 1, kColour = 2, kUv = 3, kFlatColour = 4;

  void bind() const { vao_.bind(); }
  const std::vector<GpuBatch>& batches() const { return batches_; }
  // Binds the batch's texture (if any) to `unit` and draws its triangles.
  void draw(const GpuBatch& batch, int texture_unit) const;
  void draw_all() const;  // every triangle, no textures bound (depth passes, masks)
  size_t vertex_count() const { return vertex_count_; }
  void bind_texture(const GpuBatch& batch, int unit) const;

  // Renderers that pick triangles per frame (SPEC C5, C6) need the GPU order of triangles:
  // slot i (indices 3i..3i+2) holds mesh triangle triangle_source()[i].
  const std::vector<uint32_t>& triangle_source() const { return triangle_source_; }
  const std::vector<uint32_t>& indices() const { return cpu_indices_; }
  // A vertex array over this mesh's vertices that reads indices from `elements` instead.
  gl::VertexArray vertex_array_with(const gl::Buffer& elements) const;

 private:
  gl::VertexArray vao_;
  gl::Buffer vertices_, indices_;
  std::vector<GpuBatch> batches_;
  std::vector<gl::Texture> textures_;  // per material; empty handle when untextured
  size_t vertex_count_ = 0;
  uint32_t total_indices_ = 0;
  std::vector<uint32_t> triangle_source_, cpu_indices_;
};

}  // namespace inkwire
