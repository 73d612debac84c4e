#include "server/tween/landmarks.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "common/luminance.hpp"
#include "common/percentile.hpp"

namespace inkwire {
namespace {

constexpr int kMinShift = 3;  // rule 4 and the runner-up of rule 5: closer than this is the same peak
constexpr int kNeighbours = 6;  // rule 7

// Offset of a parabola's vertex through three samples around a peak, in -0.5..0.5.
float parabola_peak(float left, float centre, float right) {
  const float d = left - 2.0f * centre + right;
  if (std::abs(d) < 1e-6f) return 0.0f;
  return std::clamp(0.5f * (left - right) / d, -0.5f, 0.5f);
}

cv::Rect patch_rect(const cv::Point& p, int window) { return {p.x - window / 2, p.y - window / 2, window, window}; }

bool inside(const cv::Rect& r, const cv::Size& size) {
  return r.x >= 0 && r.y >= 0 && r.x + r.width <= size.width && r.y + r.height <= size.height;
}

}  // namespace

cv::Mat grey_of(const Image& image) {
  cv::Mat grey(image.height, image.width, CV_32F);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const uint8_t* p = image.at(x, y);
      grey.at<float>(y, x) = rec601_luma<float>(p[0], p[1], p[2]) / 255.0f;
    }
  return grey;
}

bool far_from_border(const cv::Point& p, const cv::Size& size, int margin) {
  return p.x >= margin && p.y >= margin && p.x < size.width - margin && p.y < size.height - margin;
}

cv::Mat structure_strength(const cv::Mat& grey, int window) {
  cv::Mat out;
  cv::cornerMinEigenVal(grey, out, std::max(3, window / 2), 3);
  return out;
}

float self_match(const cv::Mat& grey, const cv::Point& p, int window) {
  const int reach = window / 2 + kMinShift;
  const cv::Rect patch = patch_rect(p, window);
  const cv::Rect around(patch.x - reach, patch.y - reach, window + 2 * reach, window + 2 * reach);
  if (!inside(around, grey.size())) return 1.0f;  // cannot tell: treat as not distinctive
  cv::Mat scores;
  cv::matchTemplate(grey(around), grey(patch), scores, cv::TM_CCOEFF_NORMED);
  float best = -1.0f;
  for (int y = 0; y < scores.rows; ++y)
    for (int x = 0; x < scores.cols; ++x)
      if (std::max(std::abs(x - reach), std::abs(y - reach)) >= kMinShift) best = std::max(best, scores.at<float>(y, x));
  return best;
}

PatchMatch match_patch(const cv::Mat& source, const cv::Point& p, const cv::Mat& target, glm::ivec2 search, int window) {
  PatchMatch m;
  const cv::Rect patch = patch_rect(p, window);
  if (!inside(patch, source.size())) return m;
  cv::Rect region(patch.x - search.x, patch.y - search.y, window + 2 * search.x, window + 2 * search.y);
  region &= cv::Rect(0, 0, target.cols, target.rows);
  if (region.width < window || region.height < window) return m;
  cv::Mat scores;
  cv::matchTemplate(target(region), source(patch), scores, cv::TM_CCOEFF_NORMED);
  cv::patchNaNs(scores, -1.0);  // flat target areas
  double best = 0.0;
  cv::Point at;
  cv::minMaxLoc(scores, nullptr, &best, nullptr, &at);
  m.best = float(best);
  for (int y = 0; y < scores.rows; ++y)
    for (int x = 0; x < scores.cols; ++x)
      if (std::max(std::abs(x - at.x), std::abs(y - at.y)) >= kMinShift) m.runner_up = std::max(m.runner_up, scores.at<float>(y, x));
  glm::vec2 sub(0.0f);
  if (at.x > 0 && at.x < scores.cols - 1)
    sub.x = parabola_peak(scores.at<float>(at.y, at.x - 1), scores.at<float>(at.y, at.x), scores.at<float>(at.y, at.x + 1));
  if (at.y > 0 && at.y < scores.rows - 1)
    sub.y = parabola_peak(scores.at<float>(at.y - 1, at.x), scores.at<float>(at.y, at.x), scores.at<float>(at.y + 1, at.x));
  // The score at (x, y) is the patch with its top-left corner there; its centre is window/2 on.
  m.position = glm::vec2(float(region.x + at.x + window / 2), float(region.y + at.y + window / 2)) + sub;
  return m;
}

std::vector<Landmark> find_landmarks(const cv::Mat& source, const cv::Mat& target, const LandmarkOptions& o, LandmarkStats* stats) {
  LandmarkStats s;
  const int half = o.window / 2;
  const int margin = half + half + kMinShift + 1;  // a patch and its rule-4 surroundings fit
  const cv::Mat strength = structure_strength(source, o.window);
  double strongest = 0.0;
  cv::minMaxLoc(strength, nullptr, &strongest);
  // Candidates: local maxima of structure, strongest first.
  cv::Mat dilated;
  cv::dilate(strength, dilated, cv::Mat());
  struct Candidate {
    float strength;
    cv::Point p;
  };
  std::vector<Candidate> candidates;
  for (int y = 0; y < strength.rows; ++y)
    for (int x = 0; x < strength.cols; ++x) {
      const float v = strength.at<float>(y, x);
      if (v > 0.0f && v >= dilated.at<float>(y, x)) candidates.push_back({v, {x, y}});
    }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.strength > b.strength; });
  s.candidates = int(candidates.size());

  // Rule 7 removes some afterwards: gather a few more than asked for.
  const size_t wanted = o.max_neighbour_disagreement > 0.0f ? size_t(o.count) * 3 / 2 + 4 : size_t(o.count);
  std::vector<Landmark> found;
  for (const Candidate& c : candidates) {
    if (found.size() >= wanted) break;
    if (!far_from_border(c.p, source.size(), margin)) {
      ++s.near_border;
      continue;
    }
    const glm::vec2 here(float(c.p.x), float(c.p.y));
    if (std::any_of(found.begin(), found.end(), [&](const Landmark& l) { return glm::length(l.source - here) < o.min_spacing; })) {
      ++s.too_close;
      continue;
    }
    if (c.strength < o.min_structure * strongest) {
      ++s.weak;
      continue;
    }
    if (self_match(source, c.p, o.window) > o.max_self_match) {
      ++s.not_distinctive;
      continue;
    }
    const PatchMatch forward = match_patch(source, c.p, target, o.search, o.window);
    if (forward.best < o.min_match) {
      ++s.no_match;
      continue;
    }
    if (forward.best - forward.runner_up < o.min_peak_gap) {
      ++s.not_unique;
      continue;
    }
    if (o.verify_both_ways) {
      const cv::Point there(int(std::lround(forward.position.x)), int(std::lround(forward.position.y)));
      const PatchMatch back = match_patch(target, there, source, o.search, o.window);
      const glm::vec2 round_trip = back.position + (forward.position - glm::vec2(float(there.x), float(there.y)));
      if (back.best < o.min_match || glm::length(round_trip - here) > 1.0f) {
        ++s.not_found_back;
        continue;
      }
    }
    found.push_back({here, forward.position, forward.best});
  }

  std::vector<Landmark> kept;
  if (o.max_neighbour_disagreement > 0.0f && found.size() > size_t(kNeighbours)) {
    for (const Landmark& l : found) {
      std::vector<std::pair<float, glm::vec2>> near;  // distance, displacement
      for (const Landmark& m : found)
        if (&m != &l) near.push_back({glm::length(m.source - l.source), m.target - m.source});
      std::partial_sort(near.begin(), near.begin() + kNeighbours, near.end(),
                        [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<float> xs, ys;
      for (int k = 0; k < kNeighbours; ++k) xs.push_back(near[size_t(k)].second.x), ys.push_back(near[size_t(k)].second.y);
      const glm::vec2 median(*median_in_place(std::span<float>(xs)), *median_in_place(std::span<float>(ys)));  // kNeighbours of each
      // Depth differences make neighbours move differently (parallax): allow a share of the motion.
      const float allowed = std::max(o.max_neighbour_disagreement, 0.3f * glm::length(median));
      if (glm::length((l.target - l.source) - median) > allowed) {
        ++s.inconsistent;
        continue;
      }
      if (kept.size() < size_t(o.count)) kept.push_back(l);
    }
  } else {
    kept = std::move(found);
    if (kept.size() > size_t(o.count)) kept.resize(size_t(o.count));
  }
  if (stats) *stats = s;
  return kept;
}

TweenCell cell_from_landmarks(const std::vector<Landmark>& landmarks, uint16_t source, uint16_t target) {
  TweenCell cell;
  cell.samples = {source, target};
  for (const Landmark& l : landmarks) cell.points.push_back({l.source, (l.source + l.target) * 0.5f, l.target});
  return cell;
}

}  // namespace inkwire
