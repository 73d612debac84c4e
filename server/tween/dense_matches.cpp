#include "server/tween/dense_matches.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "common/error.hpp"
#include "common/percentile.hpp"
#include "common/tween/warp_mesh.hpp"

namespace inkwire {
namespace {

cv::Mat grey8_of(const Image& image) {
  cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<uint8_t*>(image.pixels.data())), grey;
  cv::cvtColor(rgba, grey, cv::COLOR_RGBA2GRAY);
  return grey;
}

cv::Mat matte_of(const Image& image) {
  cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<uint8_t*>(image.pixels.data())), alpha;
  cv::extractChannel(rgba, alpha, 3);
  return alpha >= 128;
}

cv::Mat flow_between(const cv::Mat& from, const cv::Mat& to) {
  auto dis = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_MEDIUM);
  dis->setFinestScale(0);  // full resolution: a pixel of error at half resolution is two here
  cv::Mat flow;
  dis->calc(from, to, flow);
  return flow;
}

// How much detail a misplaced warp would double at each pixel: the gradient magnitude, blurred a
// little (an edge's neighbours double with it) and scaled so the strongest tenth of the object
// counts fully; plain parts still count a quarter (their shading smears too).
cv::Mat detail_weight(const Image& a, const cv::Mat& inside) {
  cv::Mat grey, gx, gy, magnitude;
  grey8_of(a).convertTo(grey, CV_32F, 1.0 / 255.0);
  cv::Sobel(grey, gx, CV_32F, 1, 0, 3);
  cv::Sobel(grey, gy, CV_32F, 0, 1, 3);
  cv::magnitude(gx, gy, magnitude);
  cv::GaussianBlur(magnitude, magnitude, {0, 0}, 1.5);
  const std::optional<float> strongest_tenth = masked_percentile(magnitude, inside, 0.9);  // where it starts
  const float strong = strongest_tenth ? std::max(*strongest_tenth, 1e-4f) : 1.0f;
  cv::Mat weight = cv::min(magnitude / strong, 1.0f);
  return 0.25f + 0.75f * weight;
}

// Pixels of `from` (inside its matte) whose flow lands inside `to`'s matte and comes back within
// `max_round_trip` pixels by `back`.
cv::Mat verified(const cv::Mat& flow, const cv::Mat& back, const cv::Mat& inside_from, const cv::Mat& inside_to, float max_round_trip) {
  cv::Mat reliable(flow.size(), CV_8U, cv::Scalar(0));
  const float limit = max_round_trip * max_round_trip;
  for (int y = 0; y < flow.rows; ++y)
    for (int x = 0; x < flow.cols; ++x) {
      if (!inside_from.at<uint8_t>(y, x)) continue;
      const cv::Point2f there = flow_at(flow, {float(x), float(y)});
      if (there.x < 0 || there.y < 0 || there.x > float(flow.cols - 1) || there.y > float(flow.rows - 1)) continue;
      if (!inside_to.at<uint8_t>(int(std::lround(there.y)), int(std::lround(there.x)))) continue;
      const cv::Point2f home = flow_at(back, there);
      const float dx = home.x - float(x), dy = home.y - float(y);
      if (dx * dx + dy * dy <= limit) reliable.at<uint8_t>(y, x) = 255;
    }
  return reliable;
}

}  // namespace

DenseMatches reversed(const DenseMatches& m) {
  return {.forward = m.backward, .backward = m.forward, .reliable = m.reliable_backward, .reliable_backward = m.reliable};
}

cv::Point2f flow_at(const cv::Mat& flow, cv::Point2f p) {
  const float x = std::clamp(p.x, 0.0f, float(flow.cols - 1)), y = std::clamp(p.y, 0.0f, float(flow.rows - 1));
  const int x0 = int(x), y0 = int(y);
  const int x1 = std::min(x0 + 1, flow.cols - 1), y1 = std::min(y0 + 1, flow.rows - 1);
  const float fx = x - float(x0), fy = y - float(y0);
  const auto& f00 = flow.at<cv::Vec2f>(y0, x0);
  const auto& f10 = flow.at<cv::Vec2f>(y0, x1);
  const auto& f01 = flow.at<cv::Vec2f>(y1, x0);
  const auto& f11 = flow.at<cv::Vec2f>(y1, x1);
  const cv::Vec2f top = f00 * (1 - fx) + f10 * fx, bottom = f01 * (1 - fx) + f11 * fx;
  const cv::Vec2f v = top * (1 - fy) + bottom * fy;
  return {p.x + v[0], p.y + v[1]};
}

DenseMatches dense_matches(const Image& a, const Image& b, const DenseMatchOptions& options) {
  if (a.width != b.width || a.height != b.height) throw Error("dense matches need two photos of one size");
  DenseMatches m;
  const cv::Mat grey_a = grey8_of(a), grey_b = grey8_of(b);
  const cv::Mat inside_a = options.use_mattes ? matte_of(a) : cv::Mat(a.height, a.width, CV_8U, cv::Scalar(255));
  const cv::Mat inside_b = options.use_mattes ? matte_of(b) : cv::Mat(b.height, b.width, CV_8U, cv::Scalar(255));
  m.forward = flow_between(grey_a, grey_b);
  m.backward = flow_between(grey_b, grey_a);
  m.reliable = verified(m.forward, m.backward, inside_a, inside_b, options.max_round_trip);
  m.reliable_backward = verified(m.backward, m.forward, inside_b, inside_a, options.max_round_trip);
  return m;
}

Image blend_along_flows(const Image& a, const cv::Mat& flow_a, float reach_a, const Image& b, const cv::Mat& flow_b, float reach_b, float t) {
  const auto warped = [](const Image& photo, const cv::Mat& flow, float reach) {
    cv::Mat map(photo.height, photo.width, CV_32FC2), out;
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) {
        const cv::Vec2f f = flow.at<cv::Vec2f>(y, x);
        map.at<cv::Vec2f>(y, x) = {float(x) + reach * f[0], float(y) + reach * f[1]};
      }
    const cv::Mat rgba(photo.height, photo.width, CV_8UC4, const_cast<uint8_t*>(photo.pixels.data()));
    cv::remap(rgba, out, map, {}, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    return out;
  };
  cv::Mat blended;
  cv::addWeighted(warped(a, flow_a, reach_a), 1.0 - t, warped(b, flow_b, reach_b), t, 0.0, blended);
  Image out(a.width, a.height);
  std::copy_n(blended.ptr<uint8_t>(0), out.pixels.size(), out.pixels.data());
  return out;
}

Image flow_interpolation(const Image& a, const Image& b, float t) {
  DenseMatchOptions whole;
  whole.use_mattes = false;
  const DenseMatches m = dense_matches(a, b, whole);
  return blend_along_flows(a, m.forward, -t, b, m.backward, -(1.0f - t), t);
}

cv::Mat warp_flow(const std::vector<Landmark>& points, cv::Size size) {
  // The client's warp mesh fixes the image border; so does this one.
  std::vector<glm::vec2> positions, moves;
  for (const Landmark& l : points) positions.push_back(l.source), moves.push_back(l.target - l.source);
  for (const glm::vec2& p : border_points(size.width, size.height)) positions.push_back(p), moves.push_back(glm::vec2(0.0f));
  cv::Mat flow(size, CV_32FC2, cv::Scalar(0, 0));
  for (const auto& t : delaunay_triangles(positions)) {
    const glm::vec2 p0 = positions[t[0]], p1 = positions[t[1]], p2 = positions[t[2]];
    const float det = (p1.y - p2.y) * (p0.x - p2.x) + (p2.x - p1.x) * (p0.y - p2.y);
    if (std::abs(det) < 1e-6f) continue;
    const int x0 = std::max(0, int(std::floor(std::min({p0.x, p1.x, p2.x}))));
    const int x1 = std::min(size.width - 1, int(std::ceil(std::max({p0.x, p1.x, p2.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({p0.y, p1.y, p2.y}))));
    const int y1 = std::min(size.height - 1, int(std::ceil(std::max({p0.y, p1.y, p2.y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const float w0 = ((p1.y - p2.y) * (float(x) - p2.x) + (p2.x - p1.x) * (float(y) - p2.y)) / det;
        const float w1 = ((p2.y - p0.y) * (float(x) - p2.x) + (p0.x - p2.x) * (float(y) - p2.y)) / det;
        const float w2 = 1.0f - w0 - w1;
        if (w0 < -1e-4f || w1 < -1e-4f || w2 < -1e-4f) continue;
        const glm::vec2 v = w0 * moves[t[0]] + w1 * moves[t[1]] + w2 * moves[t[2]];
        flow.at<cv::Vec2f>(y, x) = {v.x, v.y};
      }
  }
  return flow;
}

std::vector<Track> distil_tracks(const std::vector<const DenseMatches*>& flows, const Image& a, std::vector<Track> points,
                                 const DistilOptions& options) {
  if (flows.empty()) throw Error("distilling control points needs at least one flow");
  const cv::Size size = flows[0]->forward.size();
  cv::Mat reliable = flows[0]->reliable.clone();
  for (const DenseMatches* f : flows) cv::bitwise_and(reliable, f->reliable, reliable);
  const cv::Mat weight = detail_weight(a, reliable);
  const float spacing2 = options.min_spacing * options.min_spacing;
  auto far_from_all = [&](const glm::vec2& p) {
    return std::all_of(points.begin(), points.end(), [&](const Track& t) {
      const glm::vec2 d = t.source - p;
      return d.x * d.x + d.y * d.y >= spacing2;
    });
  };
  auto add = [&](int x, int y) {
    Track t{.source = {float(x), float(y)}, .targets = {}};
    for (const DenseMatches* f : flows) {
      const cv::Vec2f v = f->forward.at<cv::Vec2f>(y, x);
      t.targets.push_back({float(x) + v[0], float(y) + v[1]});
    }
    points.push_back(std::move(t));
  };
  while (int(points.size()) < options.max_points) {
    // Where the warps through the points so far miss the verified flows, by how much detail is there.
    std::vector<cv::Mat> approx;
    for (size_t k = 0; k < flows.size(); ++k) {
      std::vector<Landmark> through;
      for (const Track& t : points) through.push_back({.source = t.source, .target = t.targets[k], .match = 1.0f});
      approx.push_back(warp_flow(through, size));
    }
    struct Miss {
      float error;
      int x, y;
    };
    std::vector<Miss> misses;
    for (int y = 0; y < size.height; ++y)
      for (int x = 0; x < size.width; ++x) {
        if (!reliable.at<uint8_t>(y, x)) continue;
        float worst = 0;
        for (size_t k = 0; k < flows.size(); ++k) {
          const cv::Vec2f d = approx[k].at<cv::Vec2f>(y, x) - flows[k]->forward.at<cv::Vec2f>(y, x);
          worst = std::max(worst, d[0] * d[0] + d[1] * d[1]);
        }
        const float e = std::sqrt(worst) * weight.at<float>(y, x);
        if (e > options.tolerance) misses.push_back({e, x, y});
      }
    if (misses.empty()) break;
    std::sort(misses.begin(), misses.end(), [](const Miss& l, const Miss& r) { return l.error > r.error; });
    // The worst misses first, each far enough from every point: one point per wrong region a
    // round, the error measured again before the next (a point fixes its neighbourhood).
    const int budget = std::min(options.points_per_round, options.max_points - int(points.size()));
    const float round_spacing2 = 4.0f * spacing2;
    std::vector<glm::vec2> this_round;
    int added = 0;
    for (const Miss& m : misses) {
      if (added >= budget) break;
      const glm::vec2 p(float(m.x), float(m.y));
      if (!far_from_all(p)) continue;
      if (std::any_of(this_round.begin(), this_round.end(), [&](const glm::vec2& q) {
            const glm::vec2 d = q - p;
            return d.x * d.x + d.y * d.y < round_spacing2;
          }))
        continue;
      add(m.x, m.y);
      this_round.push_back(p);
      ++added;
    }
    if (added == 0) break;
  }
  return points;
}

}  // namespace inkwire
