#pragma once
// A photo drawn as a comic (SPEC C1's look on a picture instead of a mesh): colours flattened
// into a few bands by an edge-preserving filter, the shadow band darkened by about a quarter (as
// studied cartoons do), and the photo's strong edges inked as dark lines. A call's faces in a
// comic-styled session are drawn this way (render/face/conference_view.cpp), natively and in the
// browser's module alike, so it needs nothing the module lacks (no OpenCV).
#include "common/image.hpp"

namespace inkwire {

// In place; alpha is kept. `bands`: tone bands of the luminance (2..8).
void comic_photo(Image& image, int bands = 4);

}  // namespace inkwire
