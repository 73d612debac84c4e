#pragma once
// Tweening between two images of one size along corresponding control points: morphing between
// two different faces or objects (SPEC T8) and regenerating missing video frames between two
// kept ones (T9). The same warp engine as the tween renderer: both images are warped to where
// the points are at t and blended by t, so features move instead of fading.
#include "client/render/tween/image_warper.hpp"
#include "common/tween/tween_data.hpp"

namespace inkwire {

class PairTween {
 public:
  // `cell` is a pair whose points run from `a` (t = 0) to `b` (t = 1). Throws inkwire::Error
  // when the images differ in size or the cell is not a pair. Needs a current GL context.
  PairTween(const Image& a, const Image& b, const TweenCell& cell);

  // The view at t in [0, 1] (opaque where both images are).
  Image tween(float t);
  // For comparison: the plain cross-dissolve of the two images at t, nothing moving.
  Image crossfade(float t);

  int width() const { return a_.width(); }
  int height() const { return a_.height(); }

 private:
  gl::Texture a_, b_;
  ImageWarper warper_;
  int mesh_;
};

}  // namespace inkwire
