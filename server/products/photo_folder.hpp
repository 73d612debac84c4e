#pragma once
// A shop owner's folder of turntable photos, read and checked: photos in file-name order
// (JPEG, PNG, TIFF, BMP, WebP), turned upright by their EXIF orientation, scaled to one size;
// directions equally spaced over a full turn, over `arc`, by `step` (negative when the turntable
// turned the other way: the camera's azimuth falls from photo to photo), or from a Middlebury-style
// `*_par.txt` calibration in the folder (its photos then in order of azimuth, whatever order it
// lists them in). Anything else in the folder is refused by name, except
// hidden files and the calibration's companions (*.txt).
//
// Several rows (SPEC T17): spin-viewer photographers shoot a ring at each of a few camera
// heights (elevations). Either sub-folders `row1`, `row2`, ... (the lowest camera first) or
// `rows` over the files in order; every row the same count and turn. Neighbouring rows are
// tweened in triangles (two samples of one row, one of the next), as a view sphere is.
//
// Reading is the first stage of making a product (product.hpp lists the rest in order).
#include <algorithm>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "common/image.hpp"
#include "server/products/calibrated_ring.hpp"

namespace inkwire {

struct PhotoLayout {
  float step_degrees = 0;  // the turn between consecutive photos of a row (negative: turned the other way); 0: from arc or a full turn
  float arc_degrees = 0;   // the turn from a row's first photo to its last; 0: a full turn
  int rows = 0;            // rings of photos in the folder, in file-name order; 0: the row folders there are, else 1
  std::vector<float> elevations;  // degrees, per row from the lowest; empty: level, then 15 degrees apart (less past 6 rows)
  int max_side = 2048;     // photos are kept at most this many pixels a side (the finest zoom level)
  // A calibration (Middlebury `*_par.txt`: the photos' names, order and cameras) names the photos
  // of one ring and says where each was taken from. Empty: the folder's own, if it has one and
  // `folder_calibration` says to read it (inkwire-tween shape reads one only when told).
  std::filesystem::path calibration;
  bool folder_calibration = true;
};

// Zoom (SPEC T18): a product's photos are matched, keyed and first shown at most kFirstSide
// pixels a side (a first view fetches one such photo); larger photos are also kept at finer
// levels, each twice the one before, up to the photos' own size at most max_side, fetched by
// clients only when zoomed in or full screen.
inline constexpr int kFirstSide = 512;

// What each stage of making a product says as it goes, through to add-product's output: a line
// per cell (`done` of `total` cells), or about the whole product (done = 0), e.g.
// "pair 3/24 (photo_03.jpg -> photo_04.jpg): 61 landmarks".
using PairProgress = std::function<void(int done, int total, const std::string& line)>;

// The sizes of the finer levels above `first`, coarsest first, the last `finest`: doubling, and a
// level within 1.25 times of the next left out (it would add bytes and little detail).
std::vector<glm::ivec2> zoom_levels(glm::ivec2 first, glm::ivec2 finest);

struct PhotoFolder {
  std::filesystem::path folder;
  std::vector<std::string> names;       // file names (row folder included), row after row, each in ring order
  std::vector<Image> photos;            // RGBA, all one size, at most kFirstSide pixels a side
  glm::ivec2 finest{0};                 // their size at the layout's max_side (or their own, if smaller)
  std::vector<glm::vec3> directions;    // unit, from the object toward the camera
  std::vector<std::vector<uint16_t>> cells;  // neighbouring photos to tween between: pairs round one row, else triangles
  bool closed = false;                  // the rows go all the way round
  bool even_turn_assumed = false;       // no step, arc or calibration said how far each photo turned: evenly, a full turn
  std::optional<CalibratedCamera> calibration;  // when a calibration file came with the photos
  int rows = 1;                         // photo r * columns() + c is row r's c-th
  int columns() const { return int(photos.size()) / std::max(rows, 1); }
};

// Throws inkwire::Error with a one-line reason naming the file at fault: an empty or missing
// folder, fewer than 3 photos a row, an unreadable photo, a photo whose shape differs from the
// first, a file that is not a photo, steps that do not fit, rows of different lengths.
PhotoFolder read_photo_folder(const std::filesystem::path& folder, const PhotoLayout& layout);

// Triangles between neighbouring rows of `columns` photos (photo r * columns + c is row r's c-th):
// each quad of two photos in row r and the two above them split along one diagonal. A
// triangle's first two samples are neighbours in one row, its third in the next row or the
// one before; its control points are found from the first.
std::vector<std::vector<uint16_t>> row_triangles(int rows, int columns, bool closed);

// A photo turned upright by its EXIF orientation (1-8), as a viewer shows it.
Image load_upright_photo(const std::filesystem::path& file);

// Photo `index` of `photos` read again, upright, scaled to `size`, opaque: as read_photo_folder
// read it, at another size (a zoom level). Throws inkwire::Error naming the file.
Image read_photo_at(const PhotoFolder& photos, size_t index, glm::ivec2 size);

}  // namespace inkwire
