#pragma once
// Automatic control points (SPEC T7): landmarks picked in one image and found again in a
// neighbouring one by normalised cross-correlation (NCC). Candidates must be
//   1. away from the image border,
//   2. not too close to a landmark already taken,
//   3. on strong structure (high frequency: the smaller eigenvalue of the local gradient
//      tensor, so an edge must be crossed by another to count: a lone straight edge slides),
//   4. locally distinctive (their patch matches no nearby shifted copy of itself well),
//   5. unique in the target (one clear NCC peak: the runner-up away from it is well below),
//   6. the same found back: matched from the target into the source, they land where they
//      started (optional), and
//   7. moving like their neighbours (the displacement agrees with the median of the nearest
//      landmarks', which removes matches on repeated structure that rules 4-6 let through).
// Positions are pixels with sub-pixel peaks (parabola through the NCC maximum).
#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

#include "common/image.hpp"
#include "common/tween/tween_data.hpp"

namespace inkwire {

struct LandmarkOptions {
  int count = 65;
  int window = 11;              // patch side (odd)
  float min_spacing = 8.0f;     // rule 2, pixels
  float min_structure = 0.005f; // rule 3, fraction of the image's strongest structure
  float max_self_match = 0.85f; // rule 4, NCC with the patch shifted 3..window/2+3 pixels
  float min_match = 0.85f;      // rule 5, NCC of the best match (at 0.8: 4.2% wrong over five objects, not 2.8%)
  float min_peak_gap = 0.08f;   // rule 5, best minus runner-up (3+ pixels from the best)
  glm::ivec2 search{40, 12};    // how far a landmark may move (x, y), pixels
  bool verify_both_ways = true; // rule 6
  float max_neighbour_disagreement = 4.0f;  // rule 7, pixels (0 turns the rule off)
};

struct Landmark {
  glm::vec2 source, target;
  float match = 0.0f;  // NCC at the target
};

// How many candidates each rule turned away (for tuning and reports).
struct LandmarkStats {
  int candidates = 0, near_border = 0, too_close = 0, weak = 0, not_distinctive = 0, no_match = 0, not_unique = 0,
      not_found_back = 0, inconsistent = 0;
};

// Greyscale float image (0..1) of an RGBA image.
cv::Mat grey_of(const Image& image);

// Rule 1: far enough from the border for a patch and its search.
bool far_from_border(const cv::Point& p, const cv::Size& size, int margin);
// Rule 3's measure per pixel: the smaller eigenvalue of the gradient tensor over the window.
cv::Mat structure_strength(const cv::Mat& grey, int window);
// Rule 4's measure: the best NCC of the patch at `p` with the same image shifted 3 or more
// pixels (up to window/2 + 3) in any direction.
float self_match(const cv::Mat& grey, const cv::Point& p, int window);

struct PatchMatch {
  glm::vec2 position{0.0f};  // sub-pixel
  float best = -1.0f;        // NCC at the best position
  float runner_up = -1.0f;   // best NCC at least 3 pixels from it
};
// Rules 5 and 6's measure: the patch of `source` at `p` searched for in `target` within
// `search` of `p`.
PatchMatch match_patch(const cv::Mat& source, const cv::Point& p, const cv::Mat& target, glm::ivec2 search, int window);

// All rules, strongest candidates first, until `options.count` landmarks are found.
std::vector<Landmark> find_landmarks(const cv::Mat& source, const cv::Mat& target, const LandmarkOptions& options,
                                     LandmarkStats* stats = nullptr);

// A pair cell whose points are the landmarks, halfway positions on the straight path.
TweenCell cell_from_landmarks(const std::vector<Landmark>& landmarks, uint16_t source, uint16_t target);

}  // namespace inkwire
