#pragma once
// The turntable's camera found from the mattes (SPEC T24): the focal length, each row's elevation
// and the axis's column under which the silhouettes agree best, that is under which the visual
// hull they carve (visual_hull.hpp) explains every matte (the mean IoU of the hull's silhouettes
// against them). The turn angles are given (turn_angles.hpp finds them from the matches). The
// search: coordinate descent from a first guess, each step halved when no parameter improves.
// The lowest row first, alone: the turn read both ways round (the silhouettes of a turn and of
// its mirror differ only by perspective) and the focal length tried at a few scales of the guess
// (one far off carves nothing and leaves nothing to descend); then each row above, its elevation
// first tried from the row below's up to straight down (kRoughCells); then every photo at once on
// finer hulls with smaller steps (kFineCells). Silhouettes at most kSearchSide pixels a side.
#include <vector>

#include "server/products/turntable_camera.hpp"
#include "server/products/visual_hull.hpp"

namespace inkwire {

inline constexpr int kSearchSide = 256;                   // silhouettes are searched at most this many pixels a side
inline constexpr int kRoughCells = 48, kFineCells = 96;   // hulls' cells a side: row by row, then every photo at once
inline constexpr double kClearlyBetter = 0.02;  // mean IoU by which another focal length must beat the guess's
inline constexpr double kSteepest = 89;  // degrees of elevation: a camera straight above has no level right-hand side

struct CameraFit {
  TurntableCamera camera;
  std::vector<PhotoView> views;  // as given, or mirrored when the turn reads better the other way
  double mean_iou = 0;           // at the search's size
  int evaluations = 0;
};

// Mean IoU of the hull carved under `camera` against `silhouettes`, at `cells` cells a side.
double hull_agreement(const TurntableCamera& camera, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes, int cells);

// `start`'s focal length, elevations and axis column refined; silhouettes at the camera's size.
CameraFit camera_from_mattes(const TurntableCamera& start, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes);

// A silhouette scaled by `factor` (<= 1): a pixel is inside when most of what it covers is.
Silhouette scaled_silhouette(const Silhouette& s, float factor);

}  // namespace inkwire
