#include "server/products/turn_angles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include <glm/trigonometric.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "common/error.hpp"
#include "server/products/matte.hpp"
#include "server/tween/landmarks.hpp"

namespace inkwire {

namespace {

constexpr double kFullTurn = 2 * M_PI;
constexpr int kLongest = 8;          // photos a track is followed through at most (60-80 degrees at usual steps)
constexpr int kFewestTracks = 12;    // tracks through a photo below which its azimuth is not fitted
constexpr double kSmallestStep = kFullTurn / 3600;

struct Observation {
  int column;
  float x;
  bool inlier = true;
};

struct TrackPath {
  int row;
  std::vector<Observation> seen;
  double u = 0, w = 0;  // on the turntable, across and toward the first photo's camera, in pixels
};

// Where `from`'s points are in `to`, kept (`alive`) only where tracking back lands within half a pixel.
std::vector<cv::Point2f> tracked(const cv::Mat& from, const cv::Mat& to, const std::vector<cv::Point2f>& points, std::vector<bool>& alive) {
  std::vector<cv::Point2f> there, back;
  std::vector<uint8_t> ok, ok_back;
  std::vector<float> error;
  const cv::Size window(21, 21);
  cv::calcOpticalFlowPyrLK(from, to, points, there, ok, error, window, 4);
  cv::calcOpticalFlowPyrLK(to, from, there, back, ok_back, error, window, 4);
  alive.assign(points.size(), false);
  for (size_t i = 0; i < points.size(); ++i) alive[i] = ok[i] && ok_back[i] && cv::norm(back[i] - points[i]) < 0.5;
  return there;
}

// A photo as tracking sees it: grey, and where corners may be followed.
struct TrackedPhoto {
  cv::Mat grey;    // 8-bit: Lucas-Kanade tracks bytes
  cv::Mat inside;  // 255 inside the matte and away from its outline; everywhere when it cannot be keyed
};

// Where corners may be followed: inside the matte and away from the outline. A corner of the
// outline is where the surface turns away from the camera: it slides over the object as it turns
// instead of turning with it (on a plain object most corners are such).
TrackedPhoto tracked_photo(Image photo) {
  TrackedPhoto out;
  grey_of(photo).convertTo(out.grey, CV_8U, 255);
  if (!key_plain_background(photo).keyed) {
    out.inside = cv::Mat(out.grey.size(), CV_8U, cv::Scalar(255));
    return out;
  }
  out.inside = cv::Mat(photo.height, photo.width, CV_8U);
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) out.inside.at<uint8_t>(y, x) = photo.at(x, y)[3] >= 250 ? 255 : 0;
  const int margin = std::max(3, std::max(photo.width, photo.height) / 100);
  cv::erode(out.inside, out.inside, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * margin + 1, 2 * margin + 1)));
  return out;
}

// Corners of one row of `n` photos followed round it: new corners from every photo (away from
// the points already followed), each followed on through up to kLongest photos, across the last
// photo into the first. A track that never moves a pixel and a half (the backdrop, a watermark,
// the turntable's own edge) says nothing of the turn and is dropped. Two photos are held at a
// time (`photo(c)` reads one; the first few are read again at the end of the row).
void track_row(int n, const std::function<TrackedPhoto(int)>& photo, int row, std::vector<TrackPath>& out) {
  std::vector<TrackPath> active;
  std::vector<cv::Point2f> at;
  const auto finish = [&](TrackPath&& t) {
    float low = t.seen.front().x, high = low;
    for (const Observation& o : t.seen) low = std::min(low, o.x), high = std::max(high, o.x);
    if (t.seen.size() >= 3 && high - low >= 1.5f) out.push_back(std::move(t));
  };
  TrackedPhoto current = photo(0);
  for (int k = 0; k < n + kLongest - 1; ++k) {
    if (k < n) {
      cv::Mat mask = current.inside.clone();
      for (const cv::Point2f& p : at) cv::circle(mask, p, 5, cv::Scalar(0), -1);
      std::vector<cv::Point2f> corners;
      cv::goodFeaturesToTrack(current.grey, corners, 1500, 0.002, 4, mask);
      for (const cv::Point2f& c : corners) {
        active.push_back({row, {{k % n, c.x}}});
        at.push_back(c);
      }
    }
    TrackedPhoto next = photo((k + 1) % n);
    if (at.empty()) {
      current = std::move(next);
      continue;
    }
    std::vector<bool> alive;
    const std::vector<cv::Point2f> there = tracked(current.grey, next.grey, at, alive);
    std::vector<TrackPath> still;
    std::vector<cv::Point2f> still_at;
    for (size_t i = 0; i < active.size(); ++i) {
      const cv::Point p(cvRound(there[i].x), cvRound(there[i].y));
      if (alive[i] && !(p.inside(cv::Rect({}, next.inside.size())) && next.inside.at<uint8_t>(p))) alive[i] = false;
      if (alive[i]) active[i].seen.push_back({(k + 1) % n, there[i].x});
      if (alive[i] && int(active[i].seen.size()) < kLongest) {
        still.push_back(std::move(active[i]));
        still_at.push_back(there[i]);
      } else {
        finish(std::move(active[i]));
      }
    }
    active = std::move(still);
    at = std::move(still_at);
    current = std::move(next);
  }
  for (TrackPath& t : active) finish(std::move(t));
}

// Where a track's point is across the picture at azimuth a, from the row's axis column x0 and
// perspective g (1 / the focal length in pixels, over the cosine of the camera's elevation):
// x - x0 = X / (1 - g Z), X = u cos a - w sin a across, Z = u sin a + w cos a toward the camera.
struct Seen {
  double x, across, toward, shrink;  // x - x0 predicted, X, Z, 1 - g Z
};
Seen seen_at(const TrackPath& t, double a, double g) {
  const double c = std::cos(a), s = std::sin(a), across = t.u * c - t.w * s, toward = t.u * s + t.w * c, shrink = 1 - g * toward;
  return {across / shrink, across, toward, shrink};
}

// The turn that puts every track on its curve (seen_at).
struct TurnFit {
  std::vector<double> azimuth;      // per photo of a row, radians; the first 0
  std::vector<double> axis;         // per row, the axis's column
  std::vector<double> perspective;  // per row, g
  std::vector<double> perspective_sigma;  // per row, g's standard error
};

// How far an observation lies off its track's curve under `fit`, in pixels.
double off_curve(const TrackPath& t, const Observation& o, const TurnFit& fit) {
  return o.x - fit.axis[size_t(t.row)] - seen_at(t, fit.azimuth[size_t(o.column)], fit.perspective[size_t(t.row)]).x;
}

// Every photo's azimuth (the first photo's is 0), every row's axis column and perspective and
// every track's (u, w) by Levenberg-Marquardt on the tracks' x, the tracks' unknowns
// eliminated per step (a Schur complement, as bundle adjustment does: a few thousand tracks,
// a few dozen shared unknowns). Twice along the way, observations far off their track's curve
// (a corner where edges at two depths cross, a reflection) are left out. With `even`, the
// azimuths stay evenly spaced (only the rows and tracks are fitted) and the observations left
// out are those the tracks came with: the same observations, for comparing the two fits.
TurnFit fit_turn(std::vector<TrackPath>& tracks, int n, int rows, bool even = false) {
  const int shared = n - 1 + 2 * rows;
  TurnFit fit;
  fit.azimuth.assign(size_t(n), 0.0);
  fit.axis.assign(size_t(rows), 0.0);
  fit.perspective.assign(size_t(rows), 0.0);
  fit.perspective_sigma.assign(size_t(rows), 0.0);
  std::vector<double>& azimuth = fit.azimuth;
  std::vector<double>& axis = fit.axis;
  std::vector<double>& perspective = fit.perspective;
  for (int c = 0; c < n; ++c) azimuth[size_t(c)] = kFullTurn * c / n;
  for (int r = 0; r < rows; ++r) {
    double sum = 0;
    int count = 0;
    for (const TrackPath& t : tracks)
      if (t.row == r)
        for (const Observation& o : t.seen) sum += o.x, ++count;
    axis[size_t(r)] = count ? sum / count : 0;
  }
  const auto residual = [&](const TrackPath& t, const Observation& o) { return off_curve(t, o, fit); };
  // One observation's derivatives: by the track's (u, w) and by the shared unknowns it touches
  // (its photo's azimuth unless the first, its row's axis and perspective).
  struct Derivatives {
    cv::Vec2d own;
    int at[3];
    double by[3];
  };
  const auto derivatives = [&](const TrackPath& t, const Observation& o) {
    const double a = azimuth[size_t(o.column)], g = perspective[size_t(t.row)];
    const Seen v = seen_at(t, a, g);
    const double c = std::cos(a), s = std::sin(a), q2 = v.shrink * v.shrink;
    Derivatives d;
    d.own = {c / v.shrink + v.across * g * s / q2, -s / v.shrink + v.across * g * c / q2};
    d.at[0] = even ? -1 : o.column - 1, d.by[0] = (-v.toward * v.shrink + g * v.across * v.across) / q2;
    d.at[1] = n - 1 + 2 * t.row, d.by[1] = 1;
    d.at[2] = n - 1 + 2 * t.row + 1, d.by[2] = v.across * v.toward / q2;
    return d;
  };
  const auto cost = [&] {
    double sum = 0;
    for (const TrackPath& t : tracks)
      for (const Observation& o : t.seen)
        if (o.inlier) sum += std::pow(residual(t, o), 2);
    return sum;
  };
  // Each track's (u, w) from the even azimuths first: the start.
  for (TrackPath& t : tracks) {
    cv::Matx22d normal = cv::Matx22d::zeros();
    cv::Vec2d rhs(0, 0);
    for (const Observation& o : t.seen) {
      const double a = azimuth[size_t(o.column)];
      const cv::Vec2d j(std::cos(a), -std::sin(a));
      normal += j * j.t(), rhs += j * (o.x - axis[size_t(t.row)]);
    }
    cv::Vec2d uw;
    if (cv::solve(normal, rhs, uw, cv::DECOMP_SVD)) t.u = uw[0], t.w = uw[1];
  }
  double damping = 1e-3, current = cost();
  constexpr int kOutliersAt[] = {15, 30, -1}, kSteps = 100;
  // The normal equations at the current unknowns, the tracks' own eliminated: `reduced` x step =
  // `rhs` for the shared unknowns; then each track's step from its `owns` entry.
  struct Own {
    cv::Matx22d v_inverse;
    cv::Vec2d b;
    std::vector<std::pair<int, cv::Vec2d>> w;  // shared unknown, its cross term with (u, w)
  };
  cv::Mat reduced, rhs;
  std::vector<Own> owns;
  const auto normal_equations = [&](double damping) {
    reduced = cv::Mat::zeros(shared, shared, CV_64F), rhs = cv::Mat::zeros(shared, 1, CV_64F);
    owns.assign(tracks.size(), {});
    for (size_t k = 0; k < tracks.size(); ++k) {
      const TrackPath& t = tracks[k];
      cv::Matx22d v = cv::Matx22d::zeros();
      cv::Vec2d b(0, 0);
      std::vector<std::pair<int, cv::Vec2d>> w;
      const auto cross = [&w](int at, const cv::Vec2d& value) {
        for (auto& [i, sum] : w)
          if (i == at) return void(sum += value);
        w.push_back({at, value});
      };
      for (const Observation& o : t.seen) {
        if (!o.inlier) continue;
        const Derivatives d = derivatives(t, o);
        const double e = residual(t, o);
        v += d.own * d.own.t(), b += d.own * e;
        for (int i = 0; i < 3; ++i) {
          if (d.at[i] < 0) continue;  // the first photo's azimuth is fixed (every one, when even)
          rhs.at<double>(d.at[i]) += d.by[i] * e;
          cross(d.at[i], d.own * d.by[i]);
          for (int j = 0; j < 3; ++j)
            if (d.at[j] >= 0) reduced.at<double>(d.at[i], d.at[j]) += d.by[i] * d.by[j];
        }
      }
      v(0, 0) *= 1 + damping, v(1, 1) *= 1 + damping;
      v(0, 0) += 1e-9, v(1, 1) += 1e-9;
      owns[k] = {v.inv(), b, std::move(w)};
      for (const auto& [i, wi] : owns[k].w) {
        const cv::Vec2d left = owns[k].v_inverse * wi;
        rhs.at<double>(i) -= left.dot(b);
        for (const auto& [j, wj] : owns[k].w) reduced.at<double>(i, j) -= left.dot(wj);
      }
    }
    for (int i = 0; i < shared; ++i) reduced.at<double>(i, i) += damping * reduced.at<double>(i, i) + 1e-9;
  };
  int outlier_passes = 0;
  for (int iteration = 0; iteration < kSteps; ++iteration) {
    normal_equations(damping);
    cv::Mat step;
    cv::solve(reduced, rhs, step, cv::DECOMP_SVD);
    // Try the step; keep it if it lowers the cost, else damp harder.
    const std::vector<double> azimuth_was = azimuth, axis_was = axis, perspective_was = perspective;
    std::vector<cv::Vec2d> own_was;
    for (size_t k = 0; k < tracks.size(); ++k) {
      own_was.push_back({tracks[k].u, tracks[k].w});
      cv::Vec2d rest = owns[k].b;
      for (const auto& [i, wi] : owns[k].w) rest -= wi * step.at<double>(i);
      const cv::Vec2d delta = owns[k].v_inverse * rest;
      tracks[k].u += delta[0], tracks[k].w += delta[1];
    }
    for (int c = 1; c < n; ++c) azimuth[size_t(c)] += step.at<double>(c - 1);
    for (int r = 0; r < rows; ++r) axis[size_t(r)] += step.at<double>(n - 1 + 2 * r), perspective[size_t(r)] += step.at<double>(n - 1 + 2 * r + 1);
    const double tried = cost();
    if (tried < current) {
      current = tried;
      damping = std::max(1e-7, damping / 3);
    } else {
      azimuth = azimuth_was, axis = axis_was, perspective = perspective_was;
      for (size_t k = 0; k < tracks.size(); ++k) tracks[k].u = own_was[k][0], tracks[k].w = own_was[k][1];
      damping *= 5;
    }
    // Converged (no step lowers the cost) or long enough: leave the outliers out, twice, then stop.
    if (even) {
      if (damping > 1e6) break;
    } else if (damping > 1e6 || iteration == kOutliersAt[outlier_passes]) {
      if (outlier_passes == 2) break;
      ++outlier_passes, damping = 1e-3;
      int count = 0;
      for (const TrackPath& t : tracks)
        for (const Observation& o : t.seen) count += o.inlier;
      const double limit = std::max(0.5, 3 * std::sqrt(current / std::max(count, 1)));
      for (TrackPath& t : tracks)
        for (Observation& o : t.seen) o.inlier = o.inlier && std::abs(residual(t, o)) < limit;
      current = cost();
    }
  }
  // How sure the perspective is: its variance from the undamped normal equations at the end (the
  // tracks' unknowns eliminated: what they leave uncertain is in it).
  normal_equations(0);
  cv::Mat covariance;
  cv::invert(reduced, covariance, cv::DECOMP_SVD);
  int inliers = 0;
  for (const TrackPath& t : tracks)
    for (const Observation& o : t.seen) inliers += o.inlier;
  const double variance = current / std::max(1, inliers - shared - 2 * int(tracks.size()));
  for (int r = 0; r < rows; ++r) {
    const int g = n - 1 + 2 * r + 1;
    fit.perspective_sigma[size_t(r)] = std::sqrt(std::max(0.0, variance * covariance.at<double>(g, g)));
  }
  return fit;
}

// "4.1 9.8 10.2 ..." degrees, one decimal.
std::string degrees_list(const std::vector<float>& degrees) {
  std::string out;
  for (const float d : degrees) {
    char text[16];
    std::snprintf(text, sizeof text, "%s%.1f", out.empty() ? "" : " ", d);
    out += text;
  }
  return out;
}

}  // namespace

TurnSteps turn_steps_from_photos(const PhotoFolder& photos) {
  if (!photos.closed) throw Error("steps are found from the matches only for photos that go all the way round");
  const int n = photos.columns();
  const glm::ivec2 first(photos.photos.at(0).width, photos.photos.at(0).height);
  const float scale = std::min(1.0f, float(kTurnSide) / float(std::max(photos.finest.x, photos.finest.y)));
  const glm::ivec2 size = photos.folder.empty() ? first : glm::ivec2(std::lround(float(photos.finest.x) * scale), std::lround(float(photos.finest.y) * scale));
  std::vector<TrackPath> tracks;
  for (int r = 0; r < photos.rows; ++r)
    track_row(n, [&](int c) {
      const size_t index = size_t(r * n + c);
      return tracked_photo(photos.folder.empty() ? photos.photos[index] : read_photo_at(photos, index, size));
    }, r, tracks);
  const int rows = photos.rows;
  const TurnFit fit = fit_turn(tracks, n, rows);
  std::vector<double> azimuth = fit.azimuth;
  TurnSteps out;
  out.tracked.assign(size_t(n), 0);
  const auto rms = [](const std::vector<TrackPath>& tracks, const TurnFit& fit) {
    double squares = 0;
    int count = 0;
    for (const TrackPath& t : tracks)
      for (const Observation& o : t.seen)
        if (o.inlier) squares += std::pow(off_curve(t, o, fit), 2), ++count;
    return float(std::sqrt(squares / std::max(count, 1)));
  };
  for (const TrackPath& t : tracks)
    for (const Observation& o : t.seen) out.tracked[size_t(o.column)] += o.inlier;
  out.residual = rms(tracks, fit);
  // The same observations about an evenly spaced turn: what the uneven one must clearly beat.
  std::vector<TrackPath> even_tracks = tracks;
  out.even_residual = rms(even_tracks, fit_turn(even_tracks, n, rows, true));

  // Photos with too few tracks are spaced evenly between the nearest fitted ones either side.
  std::vector<int> fitted;
  for (int c = 0; c < n; ++c)
    if (c == 0 || out.tracked[size_t(c)] >= kFewestTracks) fitted.push_back(c), out.fitted += out.tracked[size_t(c)] >= kFewestTracks;
  for (size_t k = 0; k < fitted.size(); ++k) {
    const int from = fitted[k], to = k + 1 < fitted.size() ? fitted[k + 1] : n;
    const double start = azimuth[size_t(from)], end = to == n ? kFullTurn : azimuth[size_t(to)];
    for (int c = from + 1; c < to; ++c) azimuth[size_t(c)] = start + (end - start) * (c - from) / (to - from);
  }
  std::vector<double> steps;
  double total = 0;
  for (int c = 0; c < n; ++c) {
    const double next = c + 1 < n ? azimuth[size_t(c + 1)] : kFullTurn;
    steps.push_back(std::max(kSmallestStep, std::remainder(next - azimuth[size_t(c)], kFullTurn)));
    total += steps.back();
  }
  // Which way: the sign of the fitted perspective (reported as the photos' side over the focal
  // length: 0.83 for a 45-degree lens), known when it is three standard errors from none.
  double perspective_sum = 0, variance_sum = 0;
  for (int r = 0; r < rows; ++r) perspective_sum += fit.perspective[size_t(r)], variance_sum += std::pow(fit.perspective_sigma[size_t(r)], 2);
  out.field_of_view = float(perspective_sum / rows * std::max(size.x, size.y));
  out.field_of_view_error = float(std::sqrt(variance_sum) / rows * std::max(size.x, size.y));
  out.direction_known = std::abs(perspective_sum) > 3 * std::sqrt(variance_sum);
  const double way = out.direction_known && out.field_of_view < 0 ? -1 : 1;
  for (double s : steps) out.degrees.push_back(float(way * s * kFullTurn / total * 180 / M_PI));
  return out;
}

std::vector<double> azimuth_errors(const std::vector<float>& found, const std::vector<float>& truth) {
  if (found.size() != truth.size() || found.empty()) throw Error("azimuth_errors: one found azimuth per true one");
  double offset = 0;
  for (size_t i = 0; i < found.size(); ++i) offset += std::remainder(double(truth[i]) - found[i], 360.0);
  offset /= double(found.size());
  std::vector<double> out;
  for (size_t i = 0; i < found.size(); ++i) out.push_back(std::abs(std::remainder(found[i] + offset - truth[i], 360.0)));
  return out;
}

void set_turn_steps(PhotoFolder& photos, const std::vector<float>& steps_degrees) {
  const int n = photos.columns();
  if (int(steps_degrees.size()) != n) throw Error("set_turn_steps: one step per column");
  for (int r = 0; r < photos.rows; ++r) {
    const glm::vec3 first = photos.directions[size_t(r * n)];
    const float elevation = std::asin(std::clamp(first.y, -1.0f, 1.0f));
    float azimuth = std::atan2(first.x, first.z);
    for (int c = 0; c < n; ++c) {
      photos.directions[size_t(r * n + c)] = {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
      azimuth += glm::radians(steps_degrees[size_t(c)]);
    }
  }
}

void find_turn_from_matches(PhotoFolder& photos, const PairProgress& progress) {
  if (!photos.even_turn_assumed) return;
  const TurnSteps steps = turn_steps_from_photos(photos);
  if (steps.fitted < 3) {
    if (progress)
      progress(0, int(photos.cells.size()),
               "the turn could not be found from the matches (too few corners followed round): the photos are taken as evenly "
               "spaced (give --step or --arc if they are not)");
    return;
  }
  const bool backwards = steps.direction_known && steps.field_of_view < 0;
  if (!steps.uneven()) {
    if (backwards) set_turn_steps(photos, std::vector<float>(size_t(photos.columns()), -360.0f / float(photos.columns())));
    if (progress) {
      char line[400];
      std::snprintf(line, sizeof line,
                    "the photos are evenly spaced, %s (%d of %d photos tracked: a turn with a free angle per photo fits them within "
                    "%.2f pixels, even steps within %.2f, not clearly worse)",
                    backwards ? "turned the other way" : steps.direction_known ? "turned forward" : "taken as turned forward (--step -N if not)",
                    steps.fitted, photos.columns(), steps.residual, steps.even_residual);
      progress(0, int(photos.cells.size()), line);
    }
    return;
  }
  set_turn_steps(photos, steps.degrees);
  photos.even_turn_assumed = false;
  if (!progress) return;
  std::vector<float> sizes;
  for (const float d : steps.degrees) sizes.push_back(std::abs(d));
  const auto [low, high] = std::minmax_element(sizes.begin(), sizes.end());
  const char* way = !steps.direction_known ? "forward (the perspective is too weak to tell which way: --step -N if it turned the other way)"
                    : steps.degrees[0] < 0  ? "the other way (the camera's azimuth falls)"
                                            : "forward";
  char line[400];
  std::snprintf(line, sizeof line,
                "turn from the matches (%d of %d photos tracked, within %.2f pixels, %.2f if even; perspective %.2f +- %.2f), %s: steps "
                "%.1f to %.1f degrees, %.1f if even: ",
                steps.fitted, photos.columns(), steps.residual, steps.even_residual, steps.field_of_view, steps.field_of_view_error, way, *low, *high,
                360.0 / photos.columns());
  progress(0, int(photos.cells.size()), line + degrees_list(steps.degrees));
}

}  // namespace inkwire
