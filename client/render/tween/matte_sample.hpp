#pragma once
// A product photo made ready for the warp that composes views by mattes (SPEC T14, T16), on the
// CPU. The browser does the same in client/web/render/tween/matte_sample.js, step for step;
// tests/golden/warp-vectors.json, written here, pins the two to the same bytes.
#include "common/image.hpp"

namespace inkwire {

// How far from its outline a sample's alpha says inside or outside (+-1 at this many pixels).
inline constexpr float kMatteRange = 16.0f;
// How far past the outline the object's colour is bled; further out a photo's colours are its
// floor layer on white (a shadow), kept.
inline constexpr float kBleedPixels = 1.5f;

// A photo stored laid over white, with its matte (grey in red) as alpha and, where the matte
// covers a pixel in part, the white taken out again: the object's own colour. A matte smaller
// than the photo (a finer zoom level's photo is laid over its first level's matte scaled up, as
// the server lays it: server/products/matte.cpp key_like) is scaled up bilinearly to fit.
// Throws inkwire::Error when the matte's shape does not fit the photo's.
Image object_on_matte(Image photo, const Image& matte);

// A sample with a matte (its alpha) as the warper reads it when composing by mattes: colour
// bled outward past the outline by kBleedPixels, beyond that the floor layer as it looks on
// white (the sample's own colours where its matte is 0: a shadow, or white), alpha the signed
// distance to the outline (0.5 on it, +-1 at kMatteRange pixels inside / outside), so it
// interpolates under a warp and a blend.
// A finer zoom level of a sample (`scale` texels per pixel of the sample's first level) keeps
// distances and the bleed in first-level pixels, so levels blend with one another.
Image matte_sample(const Image& image, double scale = 1.0);

// A sample with no floor layer, as matte_sample() reads one: white where its matte is 0 (a
// render leaves black there, which would read as a black floor).
Image without_floor(Image sample);

}  // namespace inkwire
