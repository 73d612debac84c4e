#include "server/products/tween_budget.hpp"

#include <algorithm>
#include <cstdint>

namespace inkwire {
namespace {

// A pair's points go from a to b, halfway on the straight line unless the shape bent it; a
// triangle's are where they are in each of its three photos.
TweenCell cell_from_tracks(const std::vector<Track>& tracks, const std::vector<uint16_t>& samples) {
  TweenCell cell{.samples = samples, .points = {}};
  for (const Track& t : tracks)
    cell.points.push_back(samples.size() == 2 ? ControlPoint{t.source, 0.5f * (t.source + t.targets[0]) + t.bulge, t.targets[0]}
                                              : ControlPoint{t.source, t.targets[0], t.targets[1]});
  return cell;
}

// Each cell's tracks (its outline's first) as the tween data carries them, every cell cut to its
// first `cap` points but never below its outline.
std::vector<TweenCell> cells_capped(const std::vector<std::vector<Track>>& tracks, const std::vector<size_t>& outline,
                                    const std::vector<std::vector<uint16_t>>& cells, size_t cap) {
  std::vector<TweenCell> out;
  for (size_t i = 0; i < tracks.size(); ++i) {
    const size_t keep = std::min(tracks[i].size(), std::max(cap, outline[i]));
    out.push_back(cell_from_tracks({tracks[i].begin(), tracks[i].begin() + std::ptrdiff_t(keep)}, cells[i]));
  }
  return out;
}

// The largest cap on every cell's points that keeps `data`'s encoded form within `max_bytes`
// (what the cells' own sizes give when nothing need go), and the cells at it.
size_t largest_cap(TweenData& data, const std::vector<std::vector<Track>>& tracks, const std::vector<size_t>& outline,
                   const std::vector<std::vector<uint16_t>>& cells, size_t max_bytes) {
  size_t most = 0;
  for (const auto& t : tracks) most = std::max(most, t.size());
  auto fits = [&](size_t cap) {
    data.cells = cells_capped(tracks, outline, cells, cap);
    return encode_tween(data).size() <= max_bytes;
  };
  if (fits(most)) return most;
  size_t low = 0, high = most;  // high does not fit; low = 0 (the outlines alone) is the floor, fitting or not
  while (high - low > 1) {
    const size_t mid = (low + high) / 2;
    (fits(mid) ? low : high) = mid;
  }
  fits(low);
  return low;
}

}  // namespace

BudgetFit fit_tween_budget(TweenData& data, const CellTracks& tracks, const std::vector<std::vector<uint16_t>>& cells, size_t max_bytes) {
  BudgetFit fit;
  data.cells = cells_capped(tracks.tracks, tracks.outline, cells, SIZE_MAX);
  fit.before = encode_tween(data).size();
  fit.cap = largest_cap(data, tracks.tracks, tracks.outline, cells, max_bytes);
  fit.after = encode_tween(data).size();
  return fit;
}

}  // namespace inkwire
