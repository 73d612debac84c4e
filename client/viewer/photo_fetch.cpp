#include "client/viewer/photo_fetch.hpp"

#include <algorithm>

#include "common/tween/view_sphere.hpp"

namespace inkwire {

int wanted_level(int first_height, const std::vector<int>& level_heights, double shown_height) {
  if (shown_height <= kLevelSlack * first_height) return 0;
  for (size_t l = 0; l < level_heights.size(); ++l)
    if (shown_height <= kLevelSlack * level_heights[l]) return int(l) + 1;
  return int(level_heights.size());
}

std::optional<PhotoFetch> next_photo_fetch(const std::vector<glm::vec3>& directions, const glm::vec3& direction, std::vector<int> drawn_from,
                                           const std::vector<bool>& has_first, const std::map<int, int>& finer_level, int wanted) {
  // Nearest first; of two as near, the one the view's cell lists first (a stable sort, as the
  // script's Array.prototype.sort is).
  std::stable_sort(drawn_from.begin(), drawn_from.end(),
                   [&](int a, int b) { return nearness(directions[size_t(a)], direction) > nearness(directions[size_t(b)], direction); });
  for (int s : drawn_from)
    if (!has_first[size_t(s)]) return PhotoFetch{s, 0};
  if (wanted > 0)
    for (int s : drawn_from)
      if (const auto it = finer_level.find(s); it == finer_level.end() || it->second < wanted) return PhotoFetch{s, wanted};
  const int other = nearest_sample(directions, direction, [&](int s) { return !has_first[size_t(s)]; });
  if (other >= 0) return PhotoFetch{other, 0};
  if (wanted == 0) return std::nullopt;
  // Zoomed in, the photos a turn comes to next: the finer level of the nearest lacking it, while
  // fewer than kFinerKept hold one, or in place of the holder it would push out (finer_to_drop())
  // when that one is farther from the view and not drawn from. Each such swap brings the holders
  // nearer the view, so a still view stops fetching.
  const auto lacks = [&](int s) {
    const auto it = finer_level.find(s);
    return it == finer_level.end() || it->second < wanted;
  };
  const int ahead = nearest_sample(directions, direction, lacks);
  if (ahead < 0) return std::nullopt;
  std::map<int, int> after = finer_level;
  after[ahead] = wanted;
  const int pushed_out = finer_to_drop(directions, ahead, after);
  if (pushed_out < 0) return PhotoFetch{ahead, wanted};
  const bool drawn = std::find(drawn_from.begin(), drawn_from.end(), pushed_out) != drawn_from.end();
  if (!drawn && nearness(directions[size_t(ahead)], direction) > nearness(directions[size_t(pushed_out)], direction))
    return PhotoFetch{ahead, wanted};
  return std::nullopt;
}

int finer_to_drop(const std::vector<glm::vec3>& directions, int added, const std::map<int, int>& finer_level) {
  if (int(finer_level.size()) <= kFinerKept) return -1;
  int farthest = -1;
  double farthest_nearness = 0.0;
  for (const auto& [sample, level] : finer_level) {  // by index
    const double n = nearness(directions[size_t(sample)], directions[size_t(added)]);
    if (farthest < 0 || n < farthest_nearness) farthest = sample, farthest_nearness = n;
  }
  return farthest;
}

}  // namespace inkwire
