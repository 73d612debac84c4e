#include "server/products/shape_matches.hpp"

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "common/percentile.hpp"
#include "common/tween/point_spread.hpp"
#include "server/products/depth_refinement.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire {
namespace {

// Where photo `from`'s surface at `pixel` (its depth map's) lands in photo `to`, and whether `to`
// sees it there: its own nearest surface is within two hull cells of the point, not in front of
// it. Nothing where `from` has no surface there, or the point is behind or beside `to`'s picture.
struct Sighting {
  glm::vec2 there;
  bool seen = false;
};
// Photo `photo`'s depth at `p` (pixels): 0 off the object, -1 outside the picture.
float depth_at(const PhotoShape& shape, size_t photo, glm::vec2 p) {
  const TurntableCamera& c = shape.camera;
  const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
  return x < 0 || y < 0 || x >= c.width || y >= c.height ? -1.0f : shape.depth[photo][size_t(y * c.width + x)];
}

std::optional<Sighting> sighting(const PhotoShape& shape, size_t from, glm::vec2 pixel, size_t to) {
  const TurntableCamera& c = shape.camera;
  const float z = depth_at(shape, from, pixel);
  if (z <= 0) return std::nullopt;
  const glm::vec3 in_to = seen_from(c, shape.views[from], pixel, z, shape.views[to]);
  if (in_to.z <= 1e-3f) return std::nullopt;
  const glm::vec2 there = to_pixel(c, in_to);
  const float other = depth_at(shape, to, there);
  if (other < 0) return std::nullopt;
  return Sighting{.there = there, .seen = other > 0 && std::abs(other - in_to.z) <= 2.0f * shape.hull.voxel};
}

// One direction of shape_matches: `from`'s pixels into `to`.
void follow_shape(const PhotoShape& shape, size_t from, size_t to, cv::Mat& flow, cv::Mat& reliable) {
  const TurntableCamera& c = shape.camera;
  flow = cv::Mat(c.height, c.width, CV_32FC2, cv::Scalar(0, 0));
  reliable = cv::Mat(c.height, c.width, CV_8U, cv::Scalar(0));
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      const glm::vec2 pixel(float(x) + 0.5f, float(y) + 0.5f);
      const std::optional<Sighting> s = sighting(shape, from, pixel, to);
      if (!s) continue;
      flow.at<cv::Vec2f>(y, x) = cv::Vec2f(s->there.x - pixel.x, s->there.y - pixel.y);
      if (s->seen) reliable.at<uint8_t>(y, x) = 255;
    }
}

// How far `to` warped onto `from` by `flow` disagrees with it at each pixel (depth_refinement.hpp).
cv::Mat disagreement(const cv::Mat& from, const cv::Mat& to, const cv::Mat& flow) {
  cv::Mat map(flow.size(), CV_32FC2);
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x) {
      const cv::Vec2f f = flow.at<cv::Vec2f>(y, x);
      map.at<cv::Vec2f>(y, x) = cv::Vec2f(float(x) + f[0], float(y) + f[1]);
    }
  return warp_disagreement(from, to, map);
}

// One direction of merged_matches; returns how many of the kept pixels came from the shape.
size_t merge(const cv::Mat& from, const cv::Mat& to, const cv::Mat& matched, const cv::Mat& matched_ok, const cv::Mat& shaped,
             const cv::Mat& shaped_ok, cv::Mat& flow, cv::Mat& reliable, size_t& kept) {
  const cv::Mat matched_error = disagreement(from, to, matched), shaped_error = disagreement(from, to, shaped);
  // Where no verified match speaks, the shape is taken only where it explains the pictures as well
  // as a verified match typically does: a hull bulging over a gap (between a temple's columns) puts
  // a surface where there is none, which no match contradicts.
  const std::optional<float> typical = masked_median(matched_error, matched_ok);
  flow = matched.clone();
  reliable = matched_ok.clone();
  size_t taken = 0;
  kept = 0;
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x) {
      const bool m = matched_ok.at<uint8_t>(y, x), s = shaped_ok.at<uint8_t>(y, x);
      const float shape_error = shaped_error.at<float>(y, x);
      if (s && (m ? shape_error < matched_error.at<float>(y, x) : !typical || shape_error <= *typical)) {
        flow.at<cv::Vec2f>(y, x) = shaped.at<cv::Vec2f>(y, x);
        reliable.at<uint8_t>(y, x) = 255;
        ++taken;
      }
      kept += reliable.at<uint8_t>(y, x) != 0;
    }
  return taken;
}

}  // namespace

DenseMatches shape_matches(const PhotoShape& shape, size_t a, size_t b) {
  DenseMatches m;
  follow_shape(shape, a, b, m.forward, m.reliable);
  follow_shape(shape, b, a, m.backward, m.reliable_backward);
  return m;
}

MergedMatches merged_matches(const DenseMatches& matched, const DenseMatches& shape, const Image& a, const Image& b) {
  const cv::Mat grey_a = grey_of(a), grey_b = grey_of(b);  // 0..1
  MergedMatches out;
  size_t kept = 0, kept_backward = 0;
  const size_t taken = merge(grey_a, grey_b, matched.forward, matched.reliable, shape.forward, shape.reliable, out.matches.forward,
                             out.matches.reliable, kept);
  merge(grey_b, grey_a, matched.backward, matched.reliable_backward, shape.backward, shape.reliable_backward, out.matches.backward,
        out.matches.reliable_backward, kept_backward);
  out.from_shape = kept ? double(taken) / double(kept) : 0;
  return out;
}

ShapeTracks shape_tracks(const PhotoShape& shape, const std::vector<uint16_t>& cell, const std::vector<Image>& photos, int count) {
  const TurntableCamera& c = shape.camera;
  // A pair's points move on arcs about the axis: each keeps where the halfway view sees it. A
  // triangle's are placed between its three photos' places as the client blends them.
  const std::optional<PhotoView> halfway =
      cell.size() == 2 ? std::optional(view_between(shape.views[cell[0]], shape.views[cell[1]], 0.5f)) : std::nullopt;
  const auto near_background = [&](size_t photo, glm::vec2 p) {
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx)
        if (depth_at(shape, photo, p + glm::vec2(dx, dy)) <= 0) return true;
    return false;
  };
  // How much detail each photo has at a pixel: the corner strength (the smaller eigenvalue of the
  // gradients' structure over a few pixels), which an edge alone does not have and texture does.
  std::vector<cv::Mat> detail;
  for (const uint16_t photo : cell) {
    cv::Mat strength;
    cv::cornerMinEigenVal(grey_of(photos[photo]), strength, 5, 3);
    detail.push_back(strength);
  }
  std::vector<Track> candidates;
  std::vector<glm::vec2> layout;  // where each sits in the warp: between its places where all see it, else where it is seen
  std::vector<bool> on_outline;
  std::vector<float> detail_at;   // of each candidate, in the photo its grid point is from
  const int step = std::max(2, std::min(c.width, c.height) / 96);
  for (size_t k = 0; k < cell.size(); ++k) {
    const size_t from = cell[k];
    for (int y = step / 2; y < c.height; y += step)
      for (int x = step / 2; x < c.width; x += step) {
        const glm::vec2 pixel(float(x) + 0.5f, float(y) + 0.5f);
        std::vector<glm::vec2> places(cell.size(), pixel);  // in each photo of the cell
        bool projected = true, seen_by_all = true, outline = near_background(from, pixel);
        for (size_t j = 0; j < cell.size(); ++j) {
          if (j == k) continue;
          const std::optional<Sighting> s = sighting(shape, from, pixel, cell[j]);
          projected = s.has_value();
          if (!s) break;
          places[j] = s->there;
          seen_by_all = seen_by_all && s->seen;
          outline = outline || (s->seen && near_background(cell[j], s->there));
        }
        // A point all see comes from the first photo's grid alone (the others' would repeat it);
        // one some photo does not see only from an outline, where it turns into or out of sight.
        if (!projected || (seen_by_all ? k != 0 : !outline)) continue;
        glm::vec2 middle(0.0f);
        for (const glm::vec2& p : places) middle += p / float(places.size());
        glm::vec2 bulge(0.0f);
        if (halfway) {
          const glm::vec3 in_halfway = seen_from(c, shape.views[from], pixel, depth_at(shape, from, pixel), *halfway);
          if (in_halfway.z <= 1e-3f) continue;
          bulge = to_pixel(c, in_halfway) - middle;
        }
        candidates.push_back({.source = places[0], .targets = std::vector<glm::vec2>(places.begin() + 1, places.end()), .bulge = bulge});
        layout.push_back(seen_by_all ? middle + bulge : pixel);
        on_outline.push_back(outline);
        detail_at.push_back(detail[k].at<float>(y, x));
      }
  }
  // Inside the outline, points go where the photos have detail (SPEC T26): a point on a plain
  // panel moves nothing a viewer sees, one on a window's corner or a logo keeps it single. The
  // more detailed half of the inner candidates is spread over; the outline's are all kept.
  std::vector<float> inner;
  for (size_t i = 0; i < candidates.size(); ++i)
    if (!on_outline[i]) inner.push_back(detail_at[i]);
  if (const std::optional<float> median_detail = median_in_place(std::span<float>(inner))) {
    const float plain = *median_detail;
    size_t kept = 0;
    for (size_t i = 0; i < candidates.size(); ++i)
      if (on_outline[i] || detail_at[i] >= plain) {
        candidates[kept] = candidates[i], layout[kept] = layout[i], on_outline[kept] = on_outline[i];
        ++kept;
      }
    candidates.resize(kept), layout.resize(kept), on_outline.resize(kept);
  }
  ShapeTracks out;
  for (const size_t i : spread_points(layout, on_outline, size_t(count) * 3 / 5, size_t(count))) {
    if (out.outline == out.tracks.size() && on_outline[i]) ++out.outline;  // the outline's, first
    out.tracks.push_back(candidates[i]);
  }
  return out;
}

}  // namespace inkwire
