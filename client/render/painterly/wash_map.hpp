#pragma once
// The medium over one captured picture (SPEC P3, P7): where paint may lie and where wet pigment
// gathers, as one texture the brush shader reads. The capture's size, top row first.
//   red:   the soft matte: 1 on the object and fading to 0 over `soft_radius` pixels beyond its
//          outline, so strokes that cross the outline fade out softly instead of ending in an
//          aliased cut-out, and no paint lies further out (the backdrop stays clean)
//   green: where a wash ends: a thin band inside the outline and the boundaries between colour
//          regions of the reference, where watercolour's pigment gathers as it dries
#include <vector>

#include "common/image.hpp"

namespace inkwire {

// Made every frame, so its buffers are kept from one picture to the next (a fresh 600 KB buffer
// costs its page faults each time).
class WashMapper {
 public:
  // `reference`'s alpha is the object's matte (>= 128 on the object). Green is left 0 unless
  // `wet_edges` asks for it (it is most of the work). The image stays until the next call.
  const Image& make(const Image& reference, float soft_radius, bool wet_edges);

 private:
  std::vector<float> matte_, soft_, scratch_;
  Image out_;
};

// Box blur of a `width` x `height` plane over (2 `radius` + 1) pixels, twice (a tent: smooth
// enough for a feather), counting what lies beyond the plane as 0. `scratch` is resized to fit.
void blur_plane(std::vector<float>& plane, int width, int height, int radius, std::vector<float>& scratch);
void blur_plane(std::vector<float>& plane, int width, int height, int radius);

}  // namespace inkwire
