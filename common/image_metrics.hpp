#pragma once
// How close a synthesised image is to the true one: PSNR and SSIM over RGB, for tests,
// benchmarks and evaluation tools. Images must be the same size (inkwire::Error otherwise).
#include <glm/vec3.hpp>

#include "common/image.hpp"

namespace inkwire {

// Peak signal-to-noise ratio over the RGB channels of every pixel, in dB (capped at 99 for
// identical images).
double psnr(const Image& a, const Image& b);
// The same over the pixels where either image is covered (alpha > 0): transparent surroundings
// that match trivially do not inflate the figure.
double psnr_covered(const Image& a, const Image& b);
// Mean structural similarity of the luma (Gaussian 11x11 window, sigma 1.5, the usual
// constants), 1 for identical images.
double ssim(const Image& a, const Image& b);

// How well two mattes agree (SPEC T14): intersection over union of the pixels each calls object
// (alpha at least half). 1 when neither has any.
double matte_iou(const Image& a, const Image& b);
// The share of `image`'s object pixels (alpha > 10%) that are see-through (alpha 10..90%) beyond
// a one-pixel antialiased edge: a ghosted outline shows up here, a crisp one does not.
double ghost_fraction(const Image& image);

// `image` (straight or premultiplied, as `premultiplied` says) laid over a plain colour.
Image over_colour(const Image& image, glm::u8vec3 colour, bool premultiplied);

}  // namespace inkwire
