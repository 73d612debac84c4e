#include "server/products/photo_shape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>

#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/error.hpp"
#include "server/products/depth_refinement.hpp"
#include "server/products/silhouette_cut.hpp"

namespace inkwire {

const char* silhouettes_named(SilhouetteSource source) {
  switch (source) {
    case SilhouetteSource::Mattes: return "mattes";
    case SilhouetteSource::Cut: return "silhouettes cut from the backdrops";
    case SilhouetteSource::FilledMattes: return "mattes filled to their outlines";
  }
  return "silhouettes";
}

PhotoSilhouettes photo_silhouettes(const PhotoFolder& photos, bool matted) {
  PhotoSilhouettes out{.source = matted ? SilhouetteSource::Mattes : SilhouetteSource::Cut};
  for (size_t i = 0; i < photos.photos.size(); ++i) {
    const Image& photo = photos.photos[i];
    if (!matted) {
      SilhouetteCut cut = cut_silhouette(photo);
      if (!cut.cut()) throw Error(photos.names[i] + ": no silhouette could be cut (" + cut.reason + ")");
      out.each.push_back(std::move(cut.silhouette));
      continue;
    }
    Silhouette s{.width = photo.width, .height = photo.height, .inside = std::vector<uint8_t>(size_t(photo.width) * size_t(photo.height), 0)};
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) s.inside[size_t(y * photo.width + x)] = photo.at(x, y)[3] > 127;
    out.each.push_back(std::move(s));
  }
  return out;
}

PhotoSilhouettes filled_to_outlines(PhotoSilhouettes silhouettes) {
  for (Silhouette& s : silhouettes.each) {
    cv::Mat inside(s.height, s.width, CV_8U, s.inside.data());
    std::vector<cv::Point> points, outline;
    cv::findNonZero(inside, points);
    if (points.size() < 3) continue;
    cv::convexHull(points, outline);
    cv::fillConvexPoly(inside, outline, 1);
  }
  if (silhouettes.source == SilhouetteSource::Mattes) silhouettes.source = SilhouetteSource::FilledMattes;
  return silhouettes;
}

PhotoShape shape_from_photos(const PhotoFolder& photos, const PhotoSilhouettes& cut_or_keyed, float field_of_view) {
  const std::vector<Silhouette>& silhouettes = cut_or_keyed.each;
  if (photos.photos.empty()) throw Error("no photos to find a shape in");
  if (silhouettes.size() != photos.photos.size()) throw Error("a shape needs one silhouette a photo");
  const int width = photos.photos[0].width, height = photos.photos[0].height, columns = photos.columns();
  std::vector<PhotoView> views;
  std::vector<float> elevations(size_t(photos.rows), 0.0f);
  float left = float(width), right = 0;
  for (size_t i = 0; i < photos.photos.size(); ++i) {
    const Silhouette& s = silhouettes[i];
    if (s.width != width || s.height != height) throw Error(photos.names[i] + ": its silhouette is not the photo's size");
    float low = float(width), high = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (s.inside[size_t(y * width + x)]) low = std::min(low, float(x)), high = std::max(high, float(x + 1));
    if (high <= low) throw Error(photos.names[i] + ": its silhouette is empty, so it says nothing about the object's shape");
    left = std::min(left, low), right = std::max(right, high);
    const glm::vec3& d = photos.directions[i];
    const int row = int(i) / columns;
    views.push_back({.azimuth_deg = glm::degrees(std::atan2(d.x, d.z)), .row = row});
    // A calibration's elevation is the answer the search is checked against, not its guess.
    if (!photos.calibration) elevations[size_t(row)] = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  }
  // The first guess: the axis midway between the outline's furthest reaches round the turn.
  const TurntableCamera start{.width = width, .height = height, .focal_px = float(std::max(width, height)) / field_of_view,
                              .elevations_deg = elevations, .axis_x = 0.5f * (left + right)};
  const CameraFit fit = camera_from_mattes(start, views, silhouettes);
  PhotoShape shape{.camera = fit.camera, .views = fit.views, .evaluations = fit.evaluations, .source = cut_or_keyed.source};
  if (photos.calibration) {
    // Carved where the calibration puts each camera: a lab's gantry does not turn about one axis
    // exactly (templeRing's cameras point up to 11 pixels either side of one axis column).
    shape.found = fit.camera;
    shape.camera.focal_px = photos.calibration->focal_px;
    shape.camera.elevations_deg = {photos.calibration->elevation_deg};
    shape.camera.axis_x = 0.5f * float(width);
    shape.views = views;
    for (size_t i = 0; i < views.size(); ++i) shape.views[i].pose = photos.calibration->poses.at(i);
  }
  shape.hull = carve_hull(shape.camera, shape.views, silhouettes, kHullCells);
  if (shape.hull.count() == 0)
    throw Error("the silhouettes carve nothing under any camera tried: some do not outline the object (parts the colour of the "
                "backdrop keyed away?) or the photos are not of one object turning about one axis");
  for (size_t v = 0; v < views.size(); ++v) {
    shape.depth.emplace_back();
    shape.iou.push_back(silhouette_iou(hull_silhouette(shape.hull, shape.camera, shape.views[v], &shape.depth.back()), silhouettes[v]));
  }
  std::vector<const Image*> pictures;
  for (const Image& photo : photos.photos) pictures.push_back(&photo);
  refine_depth(shape.depth, shape.camera, shape.views, pictures, columns, shape.hull.voxel);
  return shape;
}

double mean_iou(const PhotoShape& shape) {
  return shape.iou.empty() ? 0.0 : std::accumulate(shape.iou.begin(), shape.iou.end(), 0.0) / double(shape.iou.size());
}

PhotoShape shape_from_silhouettes(const PhotoFolder& photos, PhotoSilhouettes& silhouettes, float field_of_view,
                                  const std::function<void(const std::string&)>& say) {
  std::string why;
  try {
    PhotoShape shape = shape_from_photos(photos, silhouettes, field_of_view);
    const double iou = mean_iou(shape);
    if (silhouettes.source != SilhouetteSource::Mattes || iou >= kLeastMeanIoU) return shape;
    char line[120];
    std::snprintf(line, sizeof line, "the hull explains them poorly, IoU %.2f on average", iou);
    why = line;
  } catch (const Error& e) {
    if (silhouettes.source != SilhouetteSource::Mattes) throw;
    why = e.what();
  }
  say("the mattes give no shape (" + why + "): trying them filled to their outlines");
  silhouettes = filled_to_outlines(std::move(silhouettes));
  return shape_from_photos(photos, silhouettes, field_of_view);
}

ShapeReport report_of(const PhotoShape& shape) {
  return {.camera = shape.camera, .found = shape.found, .iou_worst = *std::min_element(shape.iou.begin(), shape.iou.end()), .source = shape.source};
}

std::string shape_summary(const PhotoShape& shape) {
  const auto [worst, best] = std::minmax_element(shape.iou.begin(), shape.iou.end());
  char line[240];
  const auto elevations = [](const TurntableCamera& camera) {
    std::string out;
    char number[32];
    for (const float e : camera.elevations_deg) {
      std::snprintf(number, sizeof number, "%s%.1f", out.empty() ? "" : " / ", e);
      out += number;
    }
    return out;
  };
  std::string out = std::string("shape from the ") + silhouettes_named(shape.source) + ": ";
  const TurntableCamera& c = shape.camera;
  if (shape.found) {
    std::snprintf(line, sizeof line, "calibrated focal length %.0f px at %d x %d (the silhouettes say %.0f, %+.1f%%), elevation ", c.focal_px, c.width,
                  c.height, shape.found->focal_px, 100.0 * (shape.found->focal_px / c.focal_px - 1.0));
    out += std::string(line) + elevations(c) + " degrees (they say " + elevations(*shape.found) + "), ";
  } else {
    std::snprintf(line, sizeof line, "focal length %.0f px at %d x %d, elevation ", c.focal_px, c.width, c.height);
    out += std::string(line) + elevations(c) + " degrees, ";
  }
  std::snprintf(line, sizeof line, "axis at column %.1f; a hull of %zu cells, IoU against the %s %.3f to %.3f", c.axis_x, shape.hull.count(),
                shape.source == SilhouetteSource::Mattes ? "mattes" : "silhouettes", *worst, *best);
  return out + line;
}

void write_shape(const PhotoShape& shape, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  write_hull_ply(shape.hull, folder / "hull.ply");
  for (size_t v = 0; v < shape.depth.size(); ++v) {
    cv::Mat depth(shape.camera.height, shape.camera.width, CV_16UC1);
    for (int y = 0; y < depth.rows; ++y)
      for (int x = 0; x < depth.cols; ++x)
        depth.at<uint16_t>(y, x) = uint16_t(std::clamp(std::lround(double(shape.depth[v][size_t(y * depth.cols + x)]) / kDepthScale), 0L, 65535L));
    const std::filesystem::path file = folder / ("depth-" + std::to_string(v + 1) + ".png");
    if (!cv::imwrite(file.string(), depth)) throw Error("cannot write " + file.string());
  }
  nlohmann::json angles = nlohmann::json::array(), iou = nlohmann::json::array();
  for (const PhotoView& v : shape.views) angles.push_back(v.azimuth_deg);
  for (const double i : shape.iou) iou.push_back(i);
  nlohmann::json camera = {{"width", shape.camera.width},
                           {"height", shape.camera.height},
                           {"focal_px", shape.camera.focal_px},
                           {"elevations_deg", shape.camera.elevations_deg},
                           {"axis_px", {shape.camera.axis_x, 0.5 * shape.camera.height}},
                           {"angles_deg", angles},
                           {"hull_iou", iou},
                           {"depth_scale", kDepthScale}};
  // With a calibration, the camera above is the calibration's (the hull and depth maps are in it)
  // and what the silhouettes gave is beside it.
  if (shape.found)
    camera["found_from_silhouettes"] = {{"focal_px", shape.found->focal_px},
                                        {"elevations_deg", shape.found->elevations_deg},
                                        {"axis_px", {shape.found->axis_x, 0.5 * shape.found->height}}};
  std::ofstream out(folder / "camera.json");
  out << camera.dump(2) << "\n";
  if (!out) throw Error("cannot write " + (folder / "camera.json").string());
}

std::optional<PhotoShape> shape_for_product(const PhotoFolder& photos, bool matted, const PairProgress& progress) {
  const auto say = [&](const std::string& line) {
    if (progress) progress(0, int(photos.cells.size()), line);
  };
  // Silhouettes from one side carve a wedge, not the object: the photos must go round it. (A ring
  // need not close as a product's pairs do: the hull only asks that no side goes unseen.)
  std::vector<float> azimuths;
  for (int c = 0; c < photos.columns(); ++c) {
    const glm::vec3& d = photos.directions[size_t(c)];
    azimuths.push_back(glm::degrees(std::atan2(d.x, d.z)));
  }
  std::sort(azimuths.begin(), azimuths.end());
  float widest = 360.0f + azimuths.front() - azimuths.back();
  for (size_t i = 1; i < azimuths.size(); ++i) widest = std::max(widest, azimuths[i] - azimuths[i - 1]);
  if (widest > kWidestGap) {
    say("no shape: the photos leave " + std::to_string(int(std::lround(widest))) + " degrees of the turn unseen (control points from the matches alone)");
    return std::nullopt;
  }
  try {
    PhotoSilhouettes silhouettes = photo_silhouettes(photos, matted);
    PhotoShape shape = shape_from_silhouettes(photos, silhouettes, kDefaultFieldOfView, say);
    if (const double iou = mean_iou(shape); iou < kLeastMeanIoU) {
      char line[160];
      std::snprintf(line, sizeof line, "no shape: the hull explains the %s poorly (IoU %.2f on average): some miss parts of the object",
                    silhouettes_named(shape.source), iou);
      say(std::string(line) + " (control points from the matches alone)");
      return std::nullopt;
    }
    say(shape_summary(shape));
    return shape;
  } catch (const Error& e) {
    say(std::string("no shape: ") + e.what() + " (control points from the matches alone)");
    return std::nullopt;
  }
}

}  // namespace inkwire
