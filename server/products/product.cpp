#include "server/products/product.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "client/gl/context.hpp"
#include "client/render/scene_object.hpp"
#include "client/render/tween/image_warper.hpp"
#include "client/render/tween/mesh_samples.hpp"
#include "common/error.hpp"
#include "common/tween/view_sphere.hpp"
#include "server/products/exposure.hpp"
#include "server/products/matte.hpp"
#include "server/products/photo_folder.hpp"
#include "server/tween/dense_matches.hpp"
#include "server/tween/landmarks.hpp"
#include "server/tween/outline.hpp"

namespace inkwire {
namespace fs = std::filesystem;

Product product_from_photos(const fs::path& folder, const PhotoProductOptions& o, const PairProgress& progress) {
  if (o.matte != "auto" && o.matte != "key" && o.matte != "none") throw Error("--matte must be auto, key or none");
  if (o.max_side < 32 || o.max_side > kMaxTweenImageSide) throw Error("--max-side must be 32.." + std::to_string(kMaxTweenImageSide));
  return product_from_photo_folder(read_photo_folder(folder, o.step_degrees, o.arc_degrees, o.max_side), o, progress, folder.string());
}

Product product_from_photo_folder(PhotoFolder photos, const PhotoProductOptions& o, const PairProgress& progress,
                                  const std::string& folder_name) {
  if (photos.photos.size() < 3) throw Error("a product needs at least 3 photos");
  const fs::path folder = folder_name;
  Product product;
  product.data.width = photos.photos[0].width;
  product.data.height = photos.photos[0].height;
  product.data.directions = photos.directions;

  // Mattes: every photo keyed, or none (a product whose samples disagree on having an outline
  // would show one only some of the way round).
  if (o.matte != "none") {
    std::vector<Image> keyed = photos.photos;
    std::string refusal;
    for (size_t i = 0; i < keyed.size() && refusal.empty(); ++i) {
      const MatteResult r = key_plain_background(keyed[i]);
      if (!r.keyed) refusal = (folder / photos.names[i]).string() + " cannot be keyed: " + r.reason;
    }
    if (refusal.empty()) {
      photos.photos = std::move(keyed);
      product.matted = true;
    } else if (o.matte == "key") {
      throw Error(refusal);
    } else if (progress) {
      progress(0, int(photos.pairs.size()), "no mattes: " + refusal + " (the photos are shown whole)");
    }
  }

  // Per neighbouring pair, verified dense matches (SPEC T15), and from them: control points (the
  // outline where there are mattes, what a view between two photos shows first when it is
  // wrong, then points wherever the warp through the points so far would double detail); how
  // much brighter the second photo is (T19).
  DistilOptions distil;
  distil.max_points = o.control_points;
  DenseMatchOptions match_options;
  match_options.use_mattes = product.matted;
  std::vector<PairExposure> exposures;
  const int total = int(photos.pairs.size());
  for (int i = 0; i < total; ++i) {
    const auto& pair = photos.pairs[size_t(i)];
    const Image& a = photos.photos[pair[0]];
    const Image& b = photos.photos[pair[1]];
    const DenseMatches matches = dense_matches(a, b, match_options);
    exposures.push_back(pair_exposure(matches, a, b, pair[0], pair[1]));
    std::vector<Landmark> outline;
    if (product.matted) outline = outline_landmarks(a, b, std::max(8, a.height / 32));
    const size_t on_outline = outline.size();
    const std::vector<Landmark> points = distil_control_points(matches, a, std::move(outline), distil);
    product.data.cells.push_back(cell_from_landmarks(points, pair[0], pair[1]));
    if (progress)
      progress(i + 1, total, photos.names[pair[0]] + " -> " + photos.names[pair[1]] + ": " + std::to_string(points.size() - on_outline) +
                                 " points from matches" + (product.matted ? ", " + std::to_string(on_outline) + " outline points" : ""));
  }
  const std::vector<glm::vec3> gains = exposure_gains(exposures, int(photos.photos.size()), photos.closed);
  float largest_change = 0;
  for (size_t i = 0; i < gains.size(); ++i) {
    apply_gain(photos.photos[i], gains[i]);
    for (int c = 0; c < 3; ++c) largest_change = std::max(largest_change, std::abs(gains[i][c] - 1.0f));
  }
  if (progress) progress(0, total, "exposure evened: the largest change " + std::to_string(int(std::lround(largest_change * 100))) + "%");
  product.images = std::move(photos.photos);
  // Photos say nothing of the camera's distance; a view at the samples' own distance shows them
  // at their own scale, which is all zooming needs.
  return product;
}

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
