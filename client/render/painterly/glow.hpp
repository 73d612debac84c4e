#pragma once
// The light a neon painting gives off (SPEC P7): the object's colours, in the palette's, spread
// beyond where they are. A glow has no detail, so it is made at a fraction of the resolution
// and drawn magnified (linear filtering smooths it).
#include "client/render/painterly/palette.hpp"
#include "common/image.hpp"

namespace inkwire {

// Premultiplied RGBA covering `reference` (top row first; alpha is the matte) grown by `margin`
// pixels on every side, one texel per `scale` x `scale` pixels, blurred over about `radius`
// pixels.
Image glow_image(const Image& reference, const Palette& palette, int radius, int margin, int scale);

}  // namespace inkwire
