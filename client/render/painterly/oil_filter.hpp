#pragma once
// SPEC P2: the classic oil-paint image filter, the baseline brushes must beat. For every pixel,
// the intensities in a (2r+1)^2 window are sorted into `levels` bins; the pixel takes the mean
// colour of the fullest bin. Our own code: a sliding window adds the column entering and drops
// the one leaving, so a pixel costs O(r) rather than O(r^2).
#include "common/image.hpp"

namespace inkwire {

// Only pixels with alpha >= 128 (the object) take part and are changed; alpha is kept.
// Throws inkwire::Error unless 1 <= radius <= 64 and 2 <= levels <= 256.
Image oil_filter(const Image& image, int radius, int levels);

}  // namespace inkwire
