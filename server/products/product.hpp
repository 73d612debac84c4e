#pragma once
// Products (SPEC T11): what a turntable session shows. N sample photos of one object with their
// view directions and mattes, and the tween data between neighbouring samples, made once at
// ingest from a folder of photos (verified dense matches) or from a mesh rendered on a ring (exact
// control points). A shop owner makes one with `inkwire-server add-product`.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/image.hpp"
#include "common/mesh_import.hpp"
#include "common/tween/tween_data.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/photo_shape.hpp"

namespace inkwire {

struct Product {
  TweenData data;             // image size, sample directions, one cell per neighbouring pair
  std::vector<Image> images;  // RGBA, data.width x data.height; alpha is the matte
  bool matted = false;        // false: the photos could not be keyed and are shown whole
  float distance_diagonals = 1.4f, fov_y_degrees = 45.0f;  // the samples' camera, for zooming
  // Zoom (SPEC T18): the sizes of the photos' finer levels, coarsest first, and sample `index`
  // at one of them, made as `first` (images[index]) was: keyed alike, its exposure evened alike.
  // Read when stored, one photo at a time: a product's photos at 2048 pixels fill gigabytes.
  std::vector<glm::ivec2> levels;
  std::function<Image(size_t index, const Image& first, glm::ivec2 size)> finer;
  std::optional<ShapeReport> shape;  // what the shape stage recovered, when it found a shape
};

struct PhotoProductOptions {
  PhotoLayout layout;      // rows, turn, elevations, size
  std::string matte = "auto";  // auto: key a plain backdrop when there is one; key: refuse if not; none
  // auto: the turntable's camera and the object's shape found from the photos' silhouettes
  // (photo_shape.hpp: the mattes, or cut from backdrops that are not plain), and a cell's control
  // points (a pair's, a triangle of rows') taken from the shape where the photos agree better
  // under it than under the matches (control_points.hpp); off: matched points only
  std::string shape = "auto";
  // Per cell at most, outline included (12 bytes each; 160 bought 0.1 dB for 20% more); a cell
  // whose points come from the shape takes half, as a mesh product takes 65 exact points.
  int control_points = 130;
  // The tween data at most this share of what a first view fetches (photos, mattes, tween data).
  // Over it, every cell gives up its last-chosen points (those that mended the least) down to one
  // cap, its outline kept: a 6 x 20 rows product needs two triangles a photo where a ring needs one
  // pair, and small photos make points dear.
  float max_tween_share = 0.05f;
};

// Reads a folder of photos taken around an object, in file-name order (see photo_folder.hpp),
// finds the turn between photos if it was not given, and control points between every
// neighbouring pair. Throws inkwire::Error with a one-line
// reason naming the file at fault.
Product product_from_photos(const std::filesystem::path& folder, const PhotoProductOptions& options,
                            const PairProgress& progress = {});
// The same from photos already read (e.g. a subset of a folder, to hold the rest out), through
// the stages in the order they run, each a file of its own: the turn (turn_angles.hpp), the
// mattes (photo_keying.hpp), the exposure (exposure.hpp), the shape (photo_shape.hpp), the
// control points (control_points.hpp), the tween data's budget (tween_budget.hpp) and the samples
// as stored (product_samples.hpp).
Product product_from_photo_folder(PhotoFolder photos, const PhotoProductOptions& options, const PairProgress& progress = {});

struct MeshProductOptions {
  int samples = 24;       // on a ring about +Y, every 360/samples degrees
  int sphere_level = -1;  // 0-2: on a geodesic sphere instead (12, 42 or 162 samples), views from any side
  int size = 512;         // square sample images
  int points = 65;        // exact control points per pair
  std::string style = "default";
  UpAxis up = UpAxis::Auto;  // which way is up in the mesh file
};

// (A mesh is made into a product by tools/mesh_product.hpp, in a process of its own: the
// serving process loads no GL.)

}  // namespace inkwire
