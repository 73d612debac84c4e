#pragma once
// Correspondence from the object's shape (SPEC T26): a pixel of photo a on the object is a point
// of the hull's surface (a's depth map), which lands in photo b where b's camera sees it, when b
// sees it at all (b's depth there agrees: not hidden behind another part). Unlike flow between
// the two pictures, this sees through parallax and occlusion: the far wheel that turns behind
// the near one is where the shape puts it. But a visual hull bulges over concavities, where its
// points are not the object's; so per pixel, the shape's motion and the matched one (verified
// optical flow) each warp b onto a, and the one under which the two pictures agree better
// (photo-consistency, over a small window) is kept: where the shape is unsure, the matches stay.
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

// Where the shape puts photo a's pixel `source` halfway between photos a and b (of one row),
// against the straight line's midpoint from its place in a to its place in b: a point turning
// about the axis moves on an arc, and the tween data's middle point can say so. Zero off the
// object, or for photos of different rows.
glm::vec2 arc_bulge(const PhotoShape& shape, size_t a, size_t b, glm::vec2 source);

}  // namespace inkwire
