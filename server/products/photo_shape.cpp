#include "server/products/photo_shape.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "common/error.hpp"
#include "server/products/depth_refinement.hpp"

namespace inkwire {

PhotoShape shape_from_photos(const PhotoFolder& photos, float field_of_view) {
  if (photos.photos.empty()) throw Error("no photos to find a shape in");
  const int width = photos.photos[0].width, height = photos.photos[0].height, columns = photos.columns();
  std::vector<Silhouette> silhouettes;
  std::vector<PhotoView> views;
  std::vector<float> elevations(size_t(photos.rows), 0.0f);
  float left = float(width), right = 0;
  for (size_t i = 0; i < photos.photos.size(); ++i) {
    const Image& photo = photos.photos[i];
    Silhouette s{.width = width, .height = height, .inside = std::vector<uint8_t>(size_t(width) * size_t(height), 0)};
    size_t inside = 0;
    float low = float(width), high = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        if (photo.at(x, y)[3] > 127) {
          s.inside[size_t(y * width + x)] = 1, ++inside;
          low = std::min(low, float(x)), high = std::max(high, float(x + 1));
        }
    if (inside == 0) throw Error(photos.names[i] + ": its matte is empty, so it says nothing about the object's shape");
    left = std::min(left, low), right = std::max(right, high);
    silhouettes.push_back(std::move(s));
    const glm::vec3& d = photos.directions[i];
    const int row = int(i) / columns;
    views.push_back({.azimuth_deg = glm::degrees(std::atan2(d.x, d.z)), .row = row});
    elevations[size_t(row)] = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  }
  // The first guess: the axis midway between the outline's furthest reaches round the turn.
  const TurntableCamera start{.width = width, .height = height, .focal_px = float(std::max(width, height)) / field_of_view,
                              .elevations_deg = elevations, .axis_x = 0.5f * (left + right)};
  const CameraFit fit = camera_from_mattes(start, views, silhouettes);
  PhotoShape shape{.camera = fit.camera, .views = fit.views, .hull = carve_hull(fit.camera, fit.views, silhouettes, kHullCells),
                   .evaluations = fit.evaluations};
  if (shape.hull.count() == 0)
    throw Error("the mattes carve nothing under any camera tried: some do not outline the object (parts the colour of the backdrop "
                "keyed away?) or the photos are not of one object turning about one axis");
  for (size_t v = 0; v < views.size(); ++v) {
    shape.depth.emplace_back();
    shape.iou.push_back(silhouette_iou(hull_silhouette(shape.hull, shape.camera, shape.views[v], &shape.depth.back()), silhouettes[v]));
  }
  std::vector<const Image*> pictures;
  for (const Image& photo : photos.photos) pictures.push_back(&photo);
  refine_depth(shape.depth, shape.camera, shape.views, pictures, columns, shape.hull.voxel);
  return shape;
}

std::string shape_summary(const PhotoShape& shape) {
  const auto [worst, best] = std::minmax_element(shape.iou.begin(), shape.iou.end());
  char line[200];
  std::snprintf(line, sizeof line, "shape from the mattes: focal length %.0f px at %d x %d, elevation", shape.camera.focal_px, shape.camera.width,
                shape.camera.height);
  std::string out = line;
  for (const float e : shape.camera.elevations_deg) {
    std::snprintf(line, sizeof line, " %.1f", e);
    out += line;
  }
  std::snprintf(line, sizeof line, " degrees, axis at column %.1f; a hull of %zu cells, IoU against the mattes %.3f to %.3f", shape.camera.axis_x,
                shape.hull.count(), *worst, *best);
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
  const nlohmann::json camera = {{"width", shape.camera.width},
                                 {"height", shape.camera.height},
                                 {"focal_px", shape.camera.focal_px},
                                 {"elevations_deg", shape.camera.elevations_deg},
                                 {"axis_px", {shape.camera.axis_x, 0.5 * shape.camera.height}},
                                 {"angles_deg", angles},
                                 {"hull_iou", iou},
                                 {"depth_scale", kDepthScale}};
  std::ofstream out(folder / "camera.json");
  out << camera.dump(2) << "\n";
  if (!out) throw Error("cannot write " + (folder / "camera.json").string());
}

std::optional<PhotoShape> shape_for_product(const PhotoFolder& photos, bool matted, const PairProgress& progress) {
  if (!matted || !photos.closed) return std::nullopt;
  const auto say = [&](const std::string& line) {
    if (progress) progress(0, int(photos.cells.size()), line);
  };
  try {
    PhotoShape shape = shape_from_photos(photos, kDefaultFieldOfView);
    say(shape_summary(shape));
    return shape;
  } catch (const Error& e) {
    say(std::string("no shape: ") + e.what() + " (control points from the matches alone)");
    return std::nullopt;
  }
}

}  // namespace inkwire
