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

inline constexpr int kHullCells = 128;            // the hull written out: cells along its longest side
inline constexpr float kDefaultFieldOfView = 0.7f;  // the photos' longer side over the focal length, when nothing says

struct PhotoShape {
  TurntableCamera camera;
  std::vector<PhotoView> views;
  VisualHull hull;
  std::vector<double> iou;                 // per photo: the hull's silhouette against its matte
  std::vector<std::vector<float>> depth;   // per photo: distance ahead of the camera, 0 off the object (the hull's, refined)
  int evaluations = 0;                     // hulls carved while finding the camera
};

// `photos` keyed (alpha is the matte); `field_of_view` the first guess of the longer side over the
// focal length (the turn fit's, or kDefaultFieldOfView). Throws inkwire::Error when a matte is
// empty or the silhouettes carve nothing (they cannot be of one object turning about one axis).
PhotoShape shape_from_photos(const PhotoFolder& photos, float field_of_view);

// What was found, in a line: the focal length, each row's elevation, the axis, the hull's IoU.
std::string shape_summary(const PhotoShape& shape);

// The pipeline's shape stage, after the exposure (exposure.hpp): with mattes of a full turn, the
// shape, said in a line; without, nothing; when the silhouettes give none, nothing, said why
// (the control points then come from the matches alone).
std::optional<PhotoShape> shape_for_product(const PhotoFolder& photos, bool matted, const PairProgress& progress);

// Writes `hull.ply`, `depth-N.png` (16-bit, depth / depth_scale; N from 1 in the photos' order)
// and `camera.json` into `folder`.
inline constexpr double kDepthScale = 1e-4;
void write_shape(const PhotoShape& shape, const std::filesystem::path& folder);

}  // namespace inkwire
