#pragma once
// A product's control points (SPEC T15, T26), the stage after the turn and the shape: per cell of
// neighbouring photos, verified dense matches from its first photo to the others and control
// points from them (the outline where there are mattes, what a view between two photos shows
// first when it is wrong, then points wherever the warp through the points so far would double
// detail); or, for a pair the recovered shape explains, points from the shape alone.
#include <vector>

#include "server/products/photo_folder.hpp"
#include "server/products/photo_shape.hpp"
#include "server/tween/dense_matches.hpp"

namespace inkwire {

struct CellTracks {
  std::vector<std::vector<Track>> tracks;  // per cell, in the order chosen (outline first)
  std::vector<size_t> outline;             // per cell: how many of its first tracks are the outline's
};

// `photos` keyed when `matted`; `shape` null without one; at most `max_points` a cell. Says each
// cell's line to `progress` as it is done.
CellTracks control_points(const PhotoFolder& photos, bool matted, const PhotoShape* shape, int max_points, const PairProgress& progress);

}  // namespace inkwire
