#include "server/products/control_points.hpp"

#include <cmath>
#include <deque>

#include "server/products/shape_matches.hpp"
#include "server/tween/landmarks.hpp"
#include "server/tween/outline.hpp"

namespace inkwire {
namespace {

// Verified dense matches between photos, each pair computed once while it is needed: between two
// rows, a quad's second triangle and the next quad's first share the pair up the column between
// them, read the other way (the same matches reversed). Only the last two pairs are kept: at 2048
// pixels a side a pair's flows and masks take 75 MB.
class MatchCache {
 public:
  MatchCache(const std::vector<Image>& photos, const DenseMatchOptions& options) : photos_(photos), options_(options) {}

  DenseMatches get(int a, int b) {
    for (const Entry& e : recent_) {
      if (e.a == a && e.b == b) return e.matches;
      if (e.a == b && e.b == a) return reversed(e.matches);
    }
    recent_.push_back({a, b, dense_matches(photos_[size_t(a)], photos_[size_t(b)], options_)});
    if (recent_.size() > kKept) recent_.pop_front();
    return recent_.back().matches;
  }

 private:
  static constexpr size_t kKept = 2;  // a triangle's two pairs
  struct Entry {
    int a, b;
    DenseMatches matches;
  };
  const std::vector<Image>& photos_;
  DenseMatchOptions options_;
  std::deque<Entry> recent_;
};

// The outline points of a cell's first two photos (row neighbours: the object's ends at one
// height stay at that height), followed into a triangle's third photo by its verified flow;
// an end the flow there does not vouch for is left out.
std::vector<Track> outline_tracks(const Image& a, const Image& b, const std::vector<DenseMatches>& flows) {
  std::vector<Track> out;
  for (const Landmark& l : outline_landmarks(a, b, std::max(8, a.height / 32))) {
    Track t{.source = l.source, .targets = {l.target}};
    bool followed = true;
    for (size_t k = 1; k < flows.size() && followed; ++k) {
      const cv::Point p(int(std::lround(l.source.x)), int(std::lround(l.source.y)));
      followed = flows[k].reliable.at<uint8_t>(p) != 0;
      const cv::Point2f there = flow_at(flows[k].forward, {l.source.x, l.source.y});
      t.targets.push_back({there.x, there.y});
    }
    if (followed) out.push_back(std::move(t));
  }
  return out;
}

}  // namespace

CellTracks control_points(const PhotoFolder& photos, bool matted, const PhotoShape* shape, int max_points, const PairProgress& progress) {
  DistilOptions distil;
  distil.max_points = max_points;
  DenseMatchOptions match_options;
  match_options.use_mattes = matted;
  MatchCache matches(photos.photos, match_options);
  CellTracks out;
  const int total = int(photos.cells.size());
  for (int i = 0; i < total; ++i) {
    const std::vector<uint16_t>& cell = photos.cells[size_t(i)];
    const Image& a = photos.photos[cell[0]];
    std::vector<DenseMatches> flows;
    std::vector<const DenseMatches*> flow_pointers;
    double from_shape = 0;
    for (size_t k = 1; k < cell.size(); ++k) {
      flows.push_back(matches.get(cell[0], cell[k]));
      if (!shape) continue;
      MergedMatches merged = merged_matches(flows.back(), shape_matches(*shape, cell[0], cell[k]), a, photos.photos[cell[k]]);
      from_shape += merged.from_shape / double(cell.size() - 1);
      if (cell.size() > 2) flows.back() = std::move(merged.matches);
    }
    // A cell the shape explains takes its points from the shape alone (a pair's middle point where
    // the halfway view sees each); one it does not, from the matches (a triangle's merged with the
    // shape's motion pixel by pixel, where that explains the photos better).
    const bool points_from_shape = shape && from_shape >= kShapeTrusted;
    std::vector<Track> points;
    size_t on_outline = 0;
    if (points_from_shape) {
      ShapeTracks exact = shape_tracks(*shape, cell, photos.photos, max_points / 2);
      points = std::move(exact.tracks);
      on_outline = exact.outline;
    } else {
      for (const DenseMatches& f : flows) flow_pointers.push_back(&f);
      std::vector<Track> outline;
      if (matted) outline = outline_tracks(a, photos.photos[cell[1]], flows);
      on_outline = outline.size();
      points = distil_tracks(flow_pointers, a, std::move(outline), distil);
    }
    out.tracks.push_back(points);
    out.outline.push_back(on_outline);
    if (progress) {
      std::string names = photos.names[cell[0]];
      for (size_t k = 1; k < cell.size(); ++k) names += (k == 1 ? " -> " : ", ") + photos.names[cell[k]];
      const std::string shape_share = std::to_string(int(std::lround(100 * from_shape))) + "%";
      std::string line = names + ": " + std::to_string(points.size() - on_outline) + " points from " + (points_from_shape ? "the shape" : "matches");
      if (points_from_shape)
        line += " (it explains " + shape_share + " of the " + (cell.size() == 2 ? "pair" : "triangle") + " better than the matches)";
      else if (shape && cell.size() == 2)
        line += " (the shape explains only " + shape_share + " of the pair better than them: not used here)";
      else if (shape)
        line += " (" + shape_share + " of the motion from the shape)";
      if (matted) line += ", " + std::to_string(on_outline) + " outline points";
      progress(i + 1, total, line);
    }
  }
  return out;
}

}  // namespace inkwire
