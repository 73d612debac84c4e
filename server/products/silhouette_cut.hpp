#pragma once
// Silhouettes of an object whose backdrop is not one plain colour (SPEC T25): a dark cloth with a
// lit floor cloth under the object (templeRing), a gradient, a studio's sweep. The plain keyer
// (matte.hpp) refuses such photos, rightly, for what customers see: its matte lays the object on
// white. The shape needs less: which pixels are the object. Cut by GrabCut (OpenCV's graph cut
// over colour models of the two sides), started from the photo's border as backdrop, what is near
// one of the border's colours as likely backdrop and the rest as likely object; used for the hull
// only, never shown.
#include <string>

#include "common/image.hpp"
#include "server/products/visual_hull.hpp"

namespace inkwire {

inline constexpr int kCutSide = 256;  // photos are cut at most this many pixels a side (the search's size, kSearchSide)

struct SilhouetteCut {
  Silhouette silhouette;  // at the photo's size; empty when not cut
  std::string reason;     // why not, when not cut
  bool cut() const { return reason.empty(); }
};

// The object's silhouette in `photo` (RGB(A); alpha ignored): the largest piece GrabCut leaves as
// object, its holes kept (a gap between a temple's columns is backdrop seen through the object,
// and a hull carves it only if the silhouette keeps it). Says why not when nothing stands out,
// the object fills the photo, or the object runs off the photo's edges (a cut-off silhouette
// would carve the object away).
SilhouetteCut cut_silhouette(const Image& photo);

}  // namespace inkwire
