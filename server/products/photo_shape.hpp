#pragma once
// A turntable's camera and the object's shape from its keyed photos (SPEC T24, T25, T27): the
// photos' mattes as silhouettes, their azimuths and rows as read (or found from the matches), the
// camera found by making the silhouettes agree (camera_from_mattes.hpp), the visual hull carved
// under it and every photo's depth map from the hull, taken in where the photos agree better
// deeper (depth_refinement.hpp); written out for a person to look at as
// `hull.ply`, `depth-N.png` and `camera.json` (docs/cli.md, inkwire-tween shape).
#include <filesystem>
#include <functional>
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

// What a hull was carved from: the mattes; silhouettes cut from backdrops that are not plain
// (silhouette_cut.hpp); or the mattes filled to their convex outlines, where the keyer took parts
// of the object for backdrop (a cream roof on white) and the mattes alone carve nothing whole.
enum class SilhouetteSource { Mattes, Cut, FilledMattes };
const char* silhouettes_named(SilhouetteSource source);  // "mattes", "silhouettes cut from the backdrops", ...

struct PhotoShape {
  TurntableCamera camera;                  // the one the hull is carved under: the calibration's where one was given
  std::vector<PhotoView> views;
  VisualHull hull;
  std::vector<double> iou;                 // per photo: the hull's silhouette against its matte
  std::vector<std::vector<float>> depth;   // per photo: distance ahead of the camera, 0 off the object (the hull's, refined)
  int evaluations = 0;                     // hulls carved while finding the camera
  std::optional<TurntableCamera> found;    // with a calibration: the camera the silhouettes gave, to check it against
  SilhouetteSource source = SilhouetteSource::Mattes;
};

// What the shape stage recovered, kept with the product for add-product's report and the bench.
struct ShapeReport {
  TurntableCamera camera;                // the hull's
  std::optional<TurntableCamera> found;  // with a calibration: what the silhouettes gave
  double iou_worst = 0;                  // the hull's silhouette against the photo it explains least
  SilhouetteSource source = SilhouetteSource::Mattes;
};
ShapeReport report_of(const PhotoShape& shape);

// The photos' silhouettes: their mattes (alpha) when `matted`, else cut from their backdrops
// (silhouette_cut.hpp). Throws inkwire::Error naming a photo that gives none, and why.
struct PhotoSilhouettes {
  std::vector<Silhouette> each;  // one per photo
  SilhouetteSource source = SilhouetteSource::Mattes;
};
PhotoSilhouettes photo_silhouettes(const PhotoFolder& photos, bool matted);
// Each silhouette filled to its convex outline (source FilledMattes): a part the matte lost inside
// the outline comes back, a hollow the outline spans is filled (the hull bulges there, and a
// pair's photo-consistency decides whether to trust it).
PhotoSilhouettes filled_to_outlines(PhotoSilhouettes silhouettes);

// `silhouettes` one per photo; `field_of_view` the first guess of the longer side over the focal
// length (the turn fit's, or kDefaultFieldOfView). The camera is searched from that guess, level,
// even where a calibration came with the photos: the calibration is what the search is checked
// against (`found`), and the hull is carved where it puts each camera (PhotoView::pose).
// Throws inkwire::Error when a silhouette is empty or they carve nothing (they cannot be of one
// object turning about one axis).
PhotoShape shape_from_photos(const PhotoFolder& photos, const PhotoSilhouettes& silhouettes, float field_of_view);

// shape_from_photos, and where mattes carve nothing or a hull under kLeastMeanIoU, again from
// them filled to their outlines (said through `say`; `silhouettes` is then what was carved from).
// Throws inkwire::Error when neither carves anything.
PhotoShape shape_from_silhouettes(const PhotoFolder& photos, PhotoSilhouettes& silhouettes, float field_of_view,
                                  const std::function<void(const std::string&)>& say);
double mean_iou(const PhotoShape& shape);  // of the hull's silhouettes against the photos'

// What was found, in a line: the focal length, each row's elevation, the axis, the hull's IoU.
std::string shape_summary(const PhotoShape& shape);

// The pipeline's shape stage, after the exposure (exposure.hpp): with silhouettes of a full turn
// (the mattes when `matted`, else cut from the backdrops), the shape, said in a line; without, or
// with a hull that explains them poorly (kLeastMeanIoU: mattes that lost part of the object carve
// it away everywhere, unless their convex outlines explain it: filled_to_outlines), nothing, said
// why (the control points then come from the matches alone).
std::optional<PhotoShape> shape_for_product(const PhotoFolder& photos, bool matted, const PairProgress& progress);

// Writes `hull.ply`, `depth-N.png` (16-bit, depth / depth_scale; N from 1 in the photos' order)
// and `camera.json` into `folder`.
inline constexpr double kDepthScale = 1e-4;
void write_shape(const PhotoShape& shape, const std::filesystem::path& folder);

}  // namespace inkwire
