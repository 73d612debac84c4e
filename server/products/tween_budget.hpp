#pragma once
// The tween data's budget (SPEC T26: at most a share of the first view's bytes), the stage after
// the control points: each cell's tracks as the tween data carries them, every cell cut to the
// same number of points, never below its outline, as many as fit.
#include <cstddef>
#include <vector>

#include "common/tween/tween_data.hpp"
#include "server/products/control_points.hpp"

namespace inkwire {

struct BudgetFit {
  size_t before = 0, after = 0;  // the tween data's encoded bytes with every point, and as cut
  size_t cap = 0;                // every cell's points cut to this many (its outline kept)
};

// Fills `data.cells` from `tracks` (one per cell of `cells`) within `max_bytes` where the
// outlines allow. Points were chosen greedily, so a cell's last are those that mended the least:
// cutting them costs least.
BudgetFit fit_tween_budget(TweenData& data, const CellTracks& tracks, const std::vector<std::vector<uint16_t>>& cells, size_t max_bytes);

// The pipeline's budget stage, after the control points: `data.cells` from `tracks` within
// `max_share` of what a first view fetches, the photos' bytes as they will be stored
// (product_samples.hpp; `photos` keyed when `matted`, their exposure evened): tween <= share x
// (photos + mattes + tween). Says the tween data's size, and any cut, in a line.
BudgetFit budget_tween_data(TweenData& data, const CellTracks& tracks, const PhotoFolder& photos, bool matted, float max_share,
                            const PairProgress& progress);

}  // namespace inkwire
