#pragma once
// The words under a call's tiles in a recorded picture (SPEC F11): each member's name, "you",
// "muted", "camera off", "no face found in your camera picture", drawn onto the frame read back
// from GL with OpenCV's Hershey font (the window draws the same with its own UI).
#include <string>
#include <vector>

#include "client/call/call_grid.hpp"
#include "common/image.hpp"

namespace inkwire {

// The caption of one tile: its name and what the member is not doing.
std::string caption_of(const CallGrid::Tile& tile);
void draw_call_captions(Image& frame, const std::vector<CallGrid::Tile>& tiles);

}  // namespace inkwire
