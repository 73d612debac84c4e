#pragma once
// Which product photo a client fetches next (SPEC T12, T18): the first level of the photos the
// view is drawn from, then their finer level when the view shows them larger than the first,
// then the other photos' first level, nearest the view first, then (zoomed in) the finer level of
// the photos nearest the view, up to kFinerKept, so a zoomed-in turn finds the next photo sharp
// instead of sharpening as it arrives. The browser's element does the
// same (client/web/common/photo_fetch.js), pinned by tests/golden/warp-vectors.json.
#include <map>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace inkwire {

// Sample `sample` at `level` (0 the first level, l > 0 the product's levels[l - 1]).
struct PhotoFetch {
  int sample = -1, level = 0;
  bool operator==(const PhotoFetch&) const = default;
};

// A level is enough while it is shown at most this many times its size.
inline constexpr double kLevelSlack = 1.25;

// The level a view needs whose photos are `shown_height` device pixels high: 0 while the first
// level (`first_height`) is enough, else the smallest of `level_heights` that is, else the finest.
int wanted_level(int first_height, const std::vector<int>& level_heights, double shown_height);

// What to fetch next for a view from `direction` drawn from `drawn_from` (view_samples()), with
// `has_first` the samples whose first level is there and `finer_level` the finer level each
// sample holding one has; `wanted` the view's level. Nothing when all of that is there.
std::optional<PhotoFetch> next_photo_fetch(const std::vector<glm::vec3>& directions, const glm::vec3& direction, std::vector<int> drawn_from,
                                           const std::vector<bool>& has_first, const std::map<int, int>& finer_level, int wanted);

// At most this many samples keep a finer level (a 2048-pixel level is 16 MB on the GPU).
inline constexpr int kFinerKept = 6;
// When sample `added` has just taken a finer level and more than kFinerKept hold one: the holder
// that gives way, the farthest from `added` (zoomed-in views turn slowly: it is needed last), the
// lowest index on a tie; -1 while none need give way.
int finer_to_drop(const std::vector<glm::vec3>& directions, int added, const std::map<int, int>& finer_level);

}  // namespace inkwire
