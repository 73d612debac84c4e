#include "server/products/exposure.hpp"

#include <algorithm>
#include <cmath>

namespace inkwire {

namespace {

// Per photo, the camera's gain, each row on its own.
CameraGains row_gains(const std::vector<glm::vec3>& backdrops, const PhotoFolder& photos) {
  CameraGains all{std::vector<glm::vec3>(photos.photos.size(), glm::vec3(1.0f)), ""};
  if (backdrops.size() != photos.photos.size()) return all.unmeasured = "no mattes, so no backdrop to read the camera on", all;
  const int columns = photos.columns();
  for (int r = 0; r < photos.rows; ++r) {
    const auto first = backdrops.begin() + long(r * columns);
    const CameraGains row = camera_gains({first, first + columns}, photos.closed);
    if (!row.unmeasured.empty()) all.unmeasured = row.unmeasured;
    std::copy(row.gains.begin(), row.gains.end(), all.gains.begin() + long(r * columns));
  }
  return all;
}

}  // namespace

CameraGains camera_gains(const std::vector<glm::vec3>& backdrops, bool closed) {
  const int n = int(backdrops.size());
  CameraGains out{std::vector<glm::vec3>(size_t(n), glm::vec3(1.0f)), ""};
  if (n < 3) return out.unmeasured = "too few photos to tell drift from light", out;
  for (const glm::vec3& b : backdrops)
    for (int c = 0; c < 3; ++c) {
      if (b[c] >= kClippedBackdrop) return out.unmeasured = "the backdrop is white to the clip, which shows no exposure", out;
      if (b[c] < 8.0f) return out.unmeasured = "the backdrop is too dark to measure", out;
    }
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      std::vector<double> around;
      for (int k : {-2, -1, 1, 2}) {
        const int j = closed ? (i + k + n) % n : i + k;
        if (j >= 0 && j < n && j != i) around.push_back(std::log(double(backdrops[size_t(j)][c])));
      }
      std::sort(around.begin(), around.end());
      const double trend = around.size() % 2 ? around[around.size() / 2] : 0.5 * (around[around.size() / 2 - 1] + around[around.size() / 2]);
      out.gains[size_t(i)][c] = float(std::exp(trend - std::log(double(backdrops[size_t(i)][c]))));
    }
  return out;
}

void apply_gain(Image& photo, const glm::vec3& gain) {
  for (size_t i = 0; i < photo.pixels.size(); i += 4)
    if (photo.pixels[i + 3] != 0)  // where a matte is 0 the floor layer is already on white
      for (int c = 0; c < 3; ++c) photo.pixels[i + size_t(c)] = uint8_t(std::clamp(std::lround(float(photo.pixels[i + size_t(c)]) * gain[c]), 0L, 255L));
}

CameraGains even_exposure(PhotoFolder& photos, const std::vector<glm::vec3>& backdrops, const PairProgress& progress) {
  CameraGains camera = row_gains(backdrops, photos);
  float largest_change = 0;
  for (size_t i = 0; i < camera.gains.size(); ++i) {
    apply_gain(photos.photos[i], camera.gains[i]);
    for (int c = 0; c < 3; ++c) largest_change = std::max(largest_change, std::abs(camera.gains[i][c] - 1.0f));
  }
  if (progress)
    progress(0, int(photos.cells.size()),
             !camera.unmeasured.empty() ? "exposure left as it was: " + camera.unmeasured
                                        : "the camera's exposure evened on the backdrop: the largest change " +
                                              std::to_string(int(std::lround(largest_change * 100))) + "%");
  return camera;
}

}  // namespace inkwire
