#pragma once
// The words under a call's tiles in a recorded picture (SPEC F11): each tile's caption_of()
// (client/call/call_grid.hpp), drawn onto the frame read back from GL with OpenCV's Hershey font
// (the window draws the same with its own UI, the browser as text of its page).
#include <string>
#include <vector>

#include "client/call/call_grid.hpp"
#include "common/image.hpp"

namespace inkwire {

void draw_call_captions(Image& frame, const std::vector<CallGrid::Tile>& tiles);

}  // namespace inkwire
