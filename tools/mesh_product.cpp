#include "tools/mesh_product.hpp"

#include "client/gl/context.hpp"
#include "client/render/scene_object.hpp"
#include "client/render/tween/matte_sample.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "common/error.hpp"
#include "common/tween/view_sphere.hpp"

namespace inkwire {
namespace fs = std::filesystem;

Product product_from_mesh(const fs::path& mesh, const MeshProductOptions& o, const PairProgress& progress) {
  if (o.samples < 3 || o.samples > 360) throw Error("--samples must be 3..360");
  if (o.size < 32 || o.size > 2048) throw Error("--size must be 32..2048");
  if (o.sphere_level > 2) throw Error("--sphere must be 0, 1 or 2 (12, 42 or 162 samples)");
  auto context = create_offscreen_context(64, 64);
  const SceneObject object = load_scene_object(mesh, 0, kSceneDiagonal, o.up);
  Product product;
  std::vector<glm::vec3> directions = ring_directions(o.samples);
  std::vector<std::vector<uint16_t>> cells = ring_cells(o.samples);
  if (o.sphere_level >= 0) {
    ViewSphere sphere = geodesic_sphere(o.sphere_level);
    directions = std::move(sphere.directions);
    cells = std::move(sphere.triangles);
  }
  const MeshSamples samples = render_mesh_samples(object, directions, o.size, product.distance_diagonals, o.style);
  product.data.width = product.data.height = o.size;
  product.data.directions = directions;
  for (size_t i = 0; i < cells.size(); ++i) {
    product.data.cells.push_back(exact_cell(samples, object, cells[i], o.points));
    if (progress)
      progress(int(i + 1), int(cells.size()),
               "samples " + std::to_string(cells[i][0]) + " -> " + std::to_string(cells[i][1]) +
                   (cells[i].size() == 3 ? " -> " + std::to_string(cells[i][2]) : std::string()) + ": " +
                   std::to_string(product.data.cells.back().points.size()) + " control points");
  }
  for (const Image& image : samples.images) product.images.push_back(without_floor(image));  // a render has no floor layer
  product.matted = true;
  return product;
}

}  // namespace inkwire
