#pragma once
// A turntable's camera and the object's shape from its keyed photos (SPEC T24, T25, T27): the
// photos' mattes as silhouettes, their azimuths and rows as read (or found from the matches), the
// camera found by making the silhouettes agree (camera_from_mattes.hpp), the visual hull carved
// under it and every photo's depth map from the hull, taken in where the photos agree better
// deeper (depth_refinement.hpp); written out for a person to look at as
// `hull.ply`, `depth-N.png` and `camera.json` (names in CONTRACTS.md).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "server/products/camera_from_mattes.hpp"
#include "server/products/photo_folder.hpp"
#include "server/products/visual_hull.hpp"

namespace inkwire {

inline constexpr int kHullCells = 128;              // the hull written out: cells along its longest side
inline constexpr float kWidestGap = 60;             // degrees of the turn between neighbouring photos, at most, for a shape
inline constexpr double kLeastMeanIoU = 0.7;        // a hull explaining its silhouettes less, on average, is not the object's
inline constexpr float kDefaultFieldOfView = 0.7f;  // the photos' longer side over the focal length, when nothing says

struct PhotoShape {
  TurntableCamera camera;                  // the one the hull is carved under: the calibration's where one was given
  std::vector<PhotoView> views;
  VisualHull hull;
  std::vector<double> iou;                 // per photo: the hull's silhouette against its matte
  std::vector<std::vector<float>> depth;   // per photo: distance ahead of the camera, 0 off the object (the hull's, refined)
  int evaluations = 0;                     // hulls carved while finding the camera
  std::optional<TurntableCamera> found;    // with a calibration: the camera the silhouettes gave, to check it against
  bool cut = false;                        // silhouettes cut from backdrops that are not plain (silhouette_cut.hpp), not mattes
};

// What the shape stage recovered, kept with the product for add-product's report and the bench.
struct ShapeReport {
  TurntableCamera camera;                // the hull's
  std::optional<TurntableCamera> found;  // with a calibration: what the silhouettes gave
  double iou_worst = 0;                  // the hull's silhouette against the photo it explains least
  bool cut = false;
};
ShapeReport report_of(const PhotoShape& shape);

// The photos' silhouettes: their mattes (alpha) when `matted`, else cut from their backdrops
// (silhouette_cut.hpp). Throws inkwire::Error naming a photo that gives none, and why.
struct PhotoSilhouettes {
  std::vector<Silhouette> each;  // one per photo
  bool cut = false;              // cut from the backdrops, not the mattes
};
PhotoSilhouettes photo_silhouettes(const PhotoFolder& photos, bool matted);

// `silhouettes` one per photo; `field_of_view` the first guess of the longer side over the focal
// length (the turn fit's, or kDefaultFieldOfView). The camera is searched from that guess, level,
// even where a calibration came with the photos: the calibration is what the search is checked
// against (`found`), and the hull is carved where it puts each camera (PhotoView::pose).
// Throws inkwire::Error when a silhouette is empty or they carve nothing (they cannot be of one
// object turning about one axis).
PhotoShape shape_from_photos(const PhotoFolder& photos, const PhotoSilhouettes& silhouettes, float field_of_view);

// What was found, in a line: the focal length, each row's elevation, the axis, the hull's IoU.
std::string shape_summary(const PhotoShape& shape);

// The pipeline's shape stage, after the exposure (exposure.hpp): with silhouettes of a full turn
// (the mattes when `matted`, else cut from the backdrops), the shape, said in a line; without, or
// with a hull that explains them poorly (kLeastMeanIoU: mattes that lost part of the object carve
// it away everywhere), nothing, said why (the control points then come from the matches alone).
std::optional<PhotoShape> shape_for_product(const PhotoFolder& photos, bool matted, const PairProgress& progress);

// Writes `hull.ply`, `depth-N.png` (16-bit, depth / depth_scale; N from 1 in the photos' order)
// and `camera.json` into `folder`.
inline constexpr double kDepthScale = 1e-4;
void write_shape(const PhotoShape& shape, const std::filesystem::path& folder);

}  // namespace inkwire
