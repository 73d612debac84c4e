#pragma once
// Control points along the outline of a turntable's neighbouring photos (SPEC T14): where the
// mattes say the object ends, row by row. A turntable turns the object about its vertical axis,
// so the left and right ends of the object at one height in one photo become its ends at the
// same height in the next. Smooth, plain objects (a glazed vase, a rubber duck) have few places
// for NCC landmarks to hold on to; their outline is always there, and it is what a view between
// two photos shows first when it is wrong.
#include <vector>

#include "common/image.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire {

// Left and right ends of the object (alpha >= 128) every `spacing` rows, in both images, for
// rows where both show it; rows within `spacing` of the object's top or bottom in either image
// are left out (there the ends slide along a nearly level edge). Positions are pixel centres.
std::vector<Landmark> outline_landmarks(const Image& a, const Image& b, int spacing = 16);

}  // namespace inkwire
