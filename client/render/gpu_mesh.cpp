#include "client/render/gpu_mesh.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include <meshoptimizer.h>

namespace inkwire {

using namespace gl;

GpuMesh::GpuMesh(const SceneObject& object) {
  const Mesh& mesh = object.mesh;
  const Topology& topo = object.topology;

  std::vector<uint32_t> order(mesh.triangles.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return mesh.material_of(a) < mesh.material_of(b); });

  // One vertex per triangle corner first (texture coordinates are per corner), then weld equal
  // corners back together so the GPU's vertex cache still sees shared vertices.
  std::vector<GpuVertex> corners;
  corners.reserve(mesh.triangles.size() * 3);
  for (uint32_t t : order) {
    const Material& mat = mesh.materials[mesh.material_of(t)];
    const glm::vec4 triangle_colour = flat_colour(mesh, t);
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = mesh.triangles[t][c];
      GpuVertex g{};
      g.position = mesh.positions[v];
      g.normal = topo.vertex_normals[v];
      g.colour = (mesh.has_colours() ? mesh.colours[v] : glm::vec4(1.0f)) * mat.base_colour;
      g.flat_colour = triangle_colour;
      // Image rows are stored top-down while GL's v runs bottom-up: flip v here, once.
      g.uv = mesh.has_uvs() ? glm::vec2(mesh.corner_uvs[t][c].x, 1.0f - mesh.corner_uvs[t][c].y) : glm::vec2(0.0f);
      corners.push_back(g);
    }
  }
  std::vector<uint32_t> remap(corners.size());
  vertex_count_ = meshopt_generateVertexRemap(remap.data(), nullptr, corners.size(), corners.data(), corners.size(), sizeof(GpuVertex));
  std::vector<GpuVertex> vertices(vertex_count_);
  meshopt_remapVertexBuffer(vertices.data(), corners.data(), corners.size(), sizeof(GpuVertex), remap.data());
  std::vector<uint32_t> indices(remap.begin(), remap.end());

  for (size_t m = 0; m < mesh.materials.size(); ++m) {
    const Image& img = object.material_images[m];
    textures_.push_back(img.empty() || !mesh.has_uvs() ? Texture() : Texture::from_image(img));
  }
  for (size_t i = 0; i < order.size(); ++i) {
    const uint32_t mat = mesh.material_of(order[i]);
    if (batches_.empty() || batches_.back().material != mat)
      batches_.push_back({uint32_t(i * 3), 0, mat, bool(textures_[mat])});
    batches_.back().index_count += 3;
  }
  // Reorder each batch's triangles for the vertex cache; batches stay contiguous. The
  // optimiser only permutes whole triangles, so each slot's source is found again by matching
  // corner indices against the order we built them in.
  std::vector<std::array<uint32_t, 3>> before(order.size());
  for (size_t i = 0; i < order.size(); ++i) before[i] = {indices[3 * i], indices[3 * i + 1], indices[3 * i + 2]};
  for (const GpuBatch& b : batches_)
    meshopt_optimizeVertexCache(&indices[b.first_index], &indices[b.first_index], b.index_count, vertex_count_);
  std::map<std::array<uint32_t, 3>, std::vector<uint32_t>> slots_of;
  for (size_t i = 0; i < before.size(); ++i) {
    auto key = before[i];
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());  // same winding, canonical start
    slots_of[key].push_back(order[i]);
  }
  triangle_source_.resize(order.size());
  for (size_t i = 0; i < order.size(); ++i) {
    std::array<uint32_t, 3> key = {indices[3 * i], indices[3 * i + 1], indices[3 * i + 2]};
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    auto& sources = slots_of[key];
    triangle_source_[i] = sources.back();
    sources.pop_back();
  }
  total_indices_ = uint32_t(indices.size());

  vertices_ = Buffer::create(vertices);
  indices_ = Buffer::create_indices(indices);
  vao_ = vertex_array_with(indices_);
  cpu_indices_ = std::move(indices);
}

VertexArray GpuMesh::vertex_array_with(const Buffer& elements) const {
  VertexArray vao = VertexArray::create();
  vao.attribute(kPosition, vertices_, 3, sizeof(GpuVertex), offsetof(GpuVertex, position));
  vao.attribute(kNormal, vertices_, 3, sizeof(GpuVertex), offsetof(GpuVertex, normal));
  vao.attribute(kColour, vertices_, 4, sizeof(GpuVertex), offsetof(GpuVertex, colour));
  vao.attribute(kUv, vertices_, 2, sizeof(GpuVertex), offsetof(GpuVertex, uv));
  vao.attribute(kFlatColour, vertices_, 4, sizeof(GpuVertex), offsetof(GpuVertex, flat_colour));
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elements.id());  // recorded in the bound vertex array
  glBindVertexArray(0);
  return vao;
}

void GpuMesh::bind_texture(const GpuBatch& batch, int unit) const {
  if (batch.textured) textures_[batch.material].bind(unit);
}

void GpuMesh::draw(const GpuBatch& batch, int texture_unit) const {
  bind_texture(batch, texture_unit);
  glDrawElements(GL_TRIANGLES, GLsizei(batch.index_count), GL_UNSIGNED_INT,
                 reinterpret_cast<const void*>(size_t(batch.first_index) * sizeof(uint32_t)));
}

void GpuMesh::draw_all() const {
  glDrawElements(GL_TRIANGLES, GLsizei(total_indices_), GL_UNSIGNED_INT, nullptr);
}

}  // namespace inkwire
