#pragma once
// Products (SPEC T11): what a turntable session shows. N sample photos of one object with their
// view directions and mattes, and the tween data between neighbouring samples, made once at
// ingest from a folder of photos (verified dense matches) or from a mesh rendered on a ring (exact
// control points). A shop owner makes one with `inkwire-server add-product`.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "common/image.hpp"
#include "common/mesh_import.hpp"
#include "common/tween/tween_data.hpp"
#include "server/products/photo_folder.hpp"

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
};

// Called once per pair as it is done: e.g. "pair 3/24 (photo_03.jpg -> photo_04.jpg): 61 landmarks".
using PairProgress = std::function<void(int done, int total, const std::string& line)>;

struct PhotoProductOptions {
  PhotoLayout layout;      // rows, turn, elevations, size
  std::string matte = "auto";  // auto: key a plain backdrop when there is one; key: refuse if not; none
  // auto: with mattes, the turntable's camera and the object's shape found from them
  // (photo_shape.hpp), and a pair's control points taken from the shape where the photos agree
  // better under it than under the matches (control_points.hpp); off: matched points only
  std::string shape = "auto";
  // Per pair at most, outline included (12 bytes each; 160 bought 0.1 dB for 20% more); a pair
  // whose points come from the shape takes half, as a mesh product takes 65 exact points.
  int control_points = 130;
  // The tween data at most this share of what a first view fetches (photos, mattes, tween data).
  // Over it, every cell gives up its last-chosen points (those that mended the least) down to one
  // cap, its outline kept: a 6 x 20 rows product needs two triangles a photo where a ring needs one
  // pair, and small photos make points dear.
  float max_tween_share = 0.05f;
};

// A sample as a product stores it: the photo (JPEG; a keyed one on white with its floor layer,
// as a shop shows it and as compresses best) and its matte (PNG of the alpha).
std::vector<uint8_t> stored_photo(const Image& image, bool matted);
std::vector<uint8_t> stored_matte(const Image& image);

// Photos whose turn no step, arc or calibration gave (`even_turn_assumed`) get their steps from
// corners tracked between row neighbours (SPEC T19, turn_angles.hpp); says the steps found
// through `progress`. Does nothing to other folders.
void find_turn_from_matches(PhotoFolder& photos, const PairProgress& progress = {});

// Reads a folder of photos taken around an object, in file-name order (see photo_folder.hpp),
// finds the turn between photos if it was not given, and control points between every
// neighbouring pair. Throws inkwire::Error with a one-line
// reason naming the file at fault.
Product product_from_photos(const std::filesystem::path& folder, const PhotoProductOptions& options,
                            const PairProgress& progress = {});
// The same from photos already read (e.g. a subset of a folder, to hold the rest out).
Product product_from_photo_folder(PhotoFolder photos, const PhotoProductOptions& options, const PairProgress& progress = {},
                                  const std::string& folder_name = "");

struct MeshProductOptions {
  int samples = 24;       // on a ring about +Y, every 360/samples degrees
  int sphere_level = -1;  // 0-2: on a geodesic sphere instead (12, 42 or 162 samples), views from any side
  int size = 512;         // square sample images
  int points = 65;        // exact control points per pair
  std::string style = "default";
  UpAxis up = UpAxis::Auto;  // which way is up in the mesh file
};

// (A mesh is made into a product by products/mesh_product.hpp, in a process of its own: the
// serving process loads no GL.)

}  // namespace inkwire
