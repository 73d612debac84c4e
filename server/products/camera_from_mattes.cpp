#include "server/products/camera_from_mattes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <thread>

namespace inkwire {
namespace {

TurntableCamera scaled_camera(TurntableCamera camera, float factor, int width, int height) {
  camera.focal_px *= factor, camera.axis_x *= factor;
  camera.width = width, camera.height = height;
  return camera;
}

}  // namespace

Silhouette scaled_silhouette(const Silhouette& s, float factor) {
  if (factor >= 1) return s;
  Silhouette out{.width = std::max(1, int(std::lround(float(s.width) * factor))), .height = std::max(1, int(std::lround(float(s.height) * factor)))};
  out.inside.assign(size_t(out.width) * size_t(out.height), 0);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const int x0 = int(float(x) / factor), x1 = std::max(x0 + 1, int(float(x + 1) / factor));
      const int y0 = int(float(y) / factor), y1 = std::max(y0 + 1, int(float(y + 1) / factor));
      int in = 0, all = 0;
      for (int sy = y0; sy < std::min(y1, s.height); ++sy)
        for (int sx = x0; sx < std::min(x1, s.width); ++sx) in += s.inside[size_t(sy * s.width + sx)], ++all;
      out.inside[size_t(y * out.width + x)] = all && 2 * in >= all;
    }
  return out;
}

double hull_agreement(const TurntableCamera& camera, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes, int cells) {
  const VisualHull hull = carve_hull(camera, views, silhouettes, cells);
  if (hull.count() == 0) return 0;
  // The photos shared among the machine's cores.
  const size_t workers = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 8);
  std::vector<double> sums(workers, 0.0);
  std::vector<std::thread> threads;
  for (size_t w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (size_t v = w; v < views.size(); v += workers) sums[w] += silhouette_iou(hull_silhouette(hull, camera, views[v]), silhouettes[v]);
    });
  for (std::thread& t : threads) t.join();
  return std::accumulate(sums.begin(), sums.end(), 0.0) / double(views.size());
}

CameraFit camera_from_mattes(const TurntableCamera& start, const std::vector<PhotoView>& views, const std::vector<Silhouette>& silhouettes) {
  const float factor = std::min(1.0f, float(kSearchSide) / float(std::max(start.width, start.height)));
  std::vector<Silhouette> small;
  for (const Silhouette& s : silhouettes) small.push_back(scaled_silhouette(s, factor));
  const size_t rows = start.elevations_deg.size();
  CameraFit fit{.camera = start, .views = views};

  // The parameters: log focal length, every row's elevation (degrees), the axis's column (pixels).
  const auto camera_of = [&](const std::vector<double>& q) {
    TurntableCamera c = start;
    c.focal_px = float(std::exp(q[0]));
    for (size_t r = 0; r < rows; ++r) c.elevations_deg[r] = float(std::clamp(q[1 + r], -kSteepest, kSteepest));
    c.axis_x = float(q[1 + rows]);
    return c;
  };
  // The photos of rows below `up_to`, on hulls of `cells` cells a side.
  struct Part {
    int cells;
    std::vector<PhotoView> views;
    std::vector<Silhouette> silhouettes;
  };
  const auto rows_below = [&](size_t up_to, const std::vector<PhotoView>& turn, int cells) {
    Part part{.cells = cells};
    for (size_t v = 0; v < turn.size(); ++v)
      if (size_t(turn[v].row) < up_to) part.views.push_back(turn[v]), part.silhouettes.push_back(small[v]);
    return part;
  };
  const auto score = [&](const std::vector<double>& q, const Part& part) {
    ++fit.evaluations;
    return hull_agreement(scaled_camera(camera_of(q), factor, small[0].width, small[0].height), part.views, part.silhouettes, part.cells);
  };
  // Coordinate descent over the parameters marked `active`, each step halved when none improves
  // (the axis's down to a quarter of a searched pixel).
  std::vector<double> finest = {0.004};
  for (size_t r = 0; r < rows; ++r) finest.push_back(0.2);
  finest.push_back(0.25 / factor);
  const auto descend = [&](std::vector<double>& p, std::vector<double> step, const std::vector<bool>& active, const Part& part) {
    double best = score(p, part);
    for (int round = 0; round < 60; ++round) {
      bool improved = false;
      for (size_t i = 0; i < p.size() && !improved; ++i)
        for (const double sign : {1.0, -1.0}) {
          if (!active[i]) break;
          std::vector<double> q = p;
          q[i] += sign * step[i];
          if (const double s = score(q, part); s > best + 1e-6) {
            best = s, p = q, improved = true;
            break;
          }
        }
      if (improved) continue;
      bool done = true;
      for (size_t i = 0; i < p.size(); ++i) {
        step[i] *= 0.5;
        done = done && (!active[i] || step[i] < finest[i]);
      }
      if (done) break;
    }
    return best;
  };
  const std::vector<double> first_steps = [&] {
    std::vector<double> s = {0.16};
    for (size_t r = 0; r < rows; ++r) s.push_back(6.0);
    s.push_back(0.02 * start.width);
    return s;
  }();

  std::vector<double> p = {std::log(double(start.focal_px))};
  for (const float e : start.elevations_deg) p.push_back(e);
  p.push_back(start.axis_x);
  // The lowest row alone: which way round the turn reads and the focal length's order of
  // magnitude (a guess far off carves nothing at all), then its parameters.
  {
    std::vector<PhotoView> mirrored = views;
    for (PhotoView& v : mirrored) v.azimuth_deg = -v.azimuth_deg;
    double best = -1;
    std::vector<double> chosen = p;
    for (const std::vector<PhotoView>* turn : {&views, static_cast<const std::vector<PhotoView>*>(&mirrored)}) {
      const Part part = rows_below(1, *turn, kRoughCells);
      for (const double scale : {1.0, 0.5, 2.0, 0.25, 4.0, 8.0}) {
        std::vector<double> q = p;
        q[0] += std::log(scale);
        if (const double s = score(q, part); s > best + (scale == 1.0 ? 1e-6 : kClearlyBetter)) best = s, chosen = q, fit.views = *turn;
      }
    }
    p = chosen;
    std::vector<bool> active(p.size(), false);
    active[0] = active[1] = active[1 + rows] = true;
    descend(p, first_steps, active, rows_below(1, fit.views, kRoughCells));
  }
  // Each row above, its elevation first tried from the row below's up to looking straight down.
  for (size_t r = 1; r < rows; ++r) {
    const Part part = rows_below(r + 1, fit.views, kRoughCells);
    double best = -1, chosen = p[1 + r];
    std::vector<double> tries = {p[1 + r]};
    for (double e = p[r] + 5; e <= kSteepest; e += 5) tries.push_back(e);
    for (const double e : tries) {
      std::vector<double> q = p;
      q[1 + r] = e;
      if (const double s = score(q, part); s > best + 1e-6) best = s, chosen = e;
    }
    p[1 + r] = chosen;
    std::vector<bool> active(p.size(), false);
    for (size_t i = 0; i <= 1 + r; ++i) active[i] = true;
    active[1 + rows] = true;
    descend(p, first_steps, active, part);
  }
  // Every photo, finer hulls, smaller steps: a coarse hull's agreement moves in steps of its cells
  // and stops a fine search early.
  std::vector<double> fine_steps = first_steps;
  for (double& s : fine_steps) s *= 0.125;
  fit.mean_iou = descend(p, fine_steps, std::vector<bool>(p.size(), true), rows_below(rows, fit.views, kFineCells));
  fit.camera = camera_of(p);
  return fit;
}

}  // namespace inkwire
