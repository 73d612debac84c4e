#include "server/products/tween_budget.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

#include "server/products/product_samples.hpp"

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

}  // namespace

BudgetFit fit_tween_budget(TweenData& data, const CellTracks& tracks, const std::vector<std::vector<uint16_t>>& cells, size_t max_bytes) {
  BudgetFit fit;
  for (const auto& t : tracks.tracks) fit.cap = std::max(fit.cap, t.size());
  const auto size_at = [&](size_t cap) {
    data.cells = cells_capped(tracks.tracks, tracks.outline, cells, cap);
    return encode_tween(data).size();
  };
  fit.before = fit.after = size_at(fit.cap);
  if (fit.before <= max_bytes) return fit;
  // The largest cap that fits: fit.cap does not; 0 (the outlines alone) is the floor, fitting or not.
  size_t low = 0, high = fit.cap;
  while (high - low > 1) {
    const size_t mid = (low + high) / 2;
    (size_at(mid) <= max_bytes ? low : high) = mid;
  }
  fit.cap = low;
  fit.after = size_at(low);
  return fit;
}

BudgetFit budget_tween_data(TweenData& data, const CellTracks& tracks, const PhotoFolder& photos, bool matted, float max_share,
                            const PairProgress& progress) {
  size_t photo_bytes = 0;
  for (const Image& photo : photos.photos) photo_bytes += stored_photo(photo, matted).size() + (matted ? stored_matte(photo).size() : 0);
  const double share = std::clamp(double(max_share), 0.0, 0.99);
  const size_t budget = size_t(share / (1.0 - share) * double(photo_bytes));
  const BudgetFit fit = fit_tween_budget(data, tracks, photos.cells, budget);
  if (!progress) return fit;
  const auto percent = [&](size_t bytes) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * double(bytes) / double(bytes + photo_bytes));
    return std::string(text);
  };
  std::string line = "tween data: " + std::to_string(fit.after) + " bytes, " + percent(fit.after) + " of the first view";
  if (fit.after < fit.before)
    line += " (every cell cut to " + std::to_string(fit.cap) + " points, its outline kept, from " + std::to_string(fit.before) + " bytes, " +
            percent(fit.before) + ")";
  if (fit.after > budget) line += ", over the " + percent(budget) + " kept to: the outlines alone are more";
  progress(0, int(photos.cells.size()), line);
  return fit;
}

}  // namespace inkwire
