#pragma once
// Correspondence from the object's shape (SPEC T26): a pixel of photo a on the object is a point
// of the hull's surface (a's depth map), which lands in photo b where b's camera sees it, when b
// sees it at all (b's depth there agrees: not hidden behind another part). Unlike flow between
// the two pictures, this sees through parallax and occlusion: the far wheel that turns behind
// the near one is where the shape puts it. But a visual hull bulges over concavities, where its
// points are not the object's; so per pixel, the shape's motion and the matched one (verified
// optical flow) each warp b onto a, and the one under which the two pictures agree better
// (photo-consistency, over a small window) is kept: where the shape is unsure, the matches stay.
// How often the shape wins says whether a cell (a pair, or a triangle of rows) trusts it; one
// that does takes its control points from the shape alone (shape_tracks).
#include "server/products/photo_shape.hpp"
#include "server/tween/dense_matches.hpp"

namespace inkwire {

// Photo a's pixels into photo b (and back) along the shape: forward and backward motions, and
// `reliable` where the point is on the object in one photo and seen by the other.
DenseMatches shape_matches(const PhotoShape& shape, size_t a, size_t b);

struct MergedMatches {
  DenseMatches matches;
  double from_shape = 0;  // of a's reliable pixels, the share whose motion came from the shape
};

// Per pixel of a (and of b, backward), the motion of `shape` or of `matched` under which the two
// photos agree better, where the motion is reliable; reliable where the one kept is.
MergedMatches merged_matches(const DenseMatches& matched, const DenseMatches& shape, const Image& a, const Image& b);

// A cell's control points from the shape alone, made as a mesh product's exact points are
// (exact_cell): points of the surface on a grid over the cell's photos, each seen by all (at its
// place in each; a pair's with its middle where the halfway view sees it) or, unseen by one, on an
// outline; inside the outline, only where the photos have detail; up to `count`, three fifths from
// the outline first, spread as common/tween/point_spread.hpp spreads. `cell` a pair or a triangle
// of rows (indices into `photos`, the shape's photos), its first photo the tracks' source.
struct ShapeTracks {
  std::vector<Track> tracks;
  size_t outline = 0;  // the first this many are the outline's
};
ShapeTracks shape_tracks(const PhotoShape& shape, const std::vector<uint16_t>& cell, const std::vector<Image>& photos, int count);

// The share of a cell's pixels whose motion the shape explains better than the matches
// (merged_matches' from_shape, over the cell's pairs) for its points to come from the shape: on
// the rendered truck every pair's is 30-79%; a shape that is not the object's (a hull over what
// the mattes miss) explains little.
inline constexpr double kShapeTrusted = 0.2;

}  // namespace inkwire
