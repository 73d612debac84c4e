#pragma once
// How close a synthesised image is to the true one: PSNR and SSIM over RGB, for tests,
// benchmarks and evaluation tools. Images must be the same size (inkwire::Error otherwise).
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

}  // namespace inkwire
