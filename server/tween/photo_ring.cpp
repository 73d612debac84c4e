#include "server/tween/photo_ring.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "common/error.hpp"
#include "common/percentile.hpp"

namespace inkwire {
namespace {

float degrees_between(const glm::vec3& a, const glm::vec3& b) {
  return float(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / 3.14159265358979);
}

}  // namespace

PhotoRing load_photo_ring(const std::filesystem::path& folder, const std::filesystem::path& calibration_file) {
  std::filesystem::path calibration = calibration_file;
  if (calibration.empty() && std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().filename().string().ends_with("_par.txt")) calibration = entry.path();
  if (calibration.empty()) throw Error(folder.string() + ": no *_par.txt calibration file (Middlebury ring layout)");
  std::ifstream in(calibration);
  if (!in) throw Error(calibration.string() + ": cannot be read");
  int count = 0;
  if (!(in >> count) || count < 3 || count > 10000) throw Error(calibration.string() + ": first line is not an image count (3..10000)");
  PhotoRing ring;
  ring.folder = folder;
  for (int i = 0; i < count; ++i) {
    std::string name;
    double v[21];
    if (!(in >> name)) throw Error(calibration.string() + ": " + std::to_string(count) + " images announced, " + std::to_string(i) + " found");
    for (double& x : v)
      if (!(in >> x) || !std::isfinite(x)) throw Error(calibration.string() + ": line for " + name + " is not 21 numbers");
    if (name.find('/') != std::string::npos || name.find("..") != std::string::npos)
      throw Error(calibration.string() + ": image name '" + name + "' is not a plain file name");
    if (!std::filesystem::exists(folder / name)) throw Error(calibration.string() + ": image " + name + " is missing");
    glm::mat3 k, r;  // rows in the file: glm is column-major, so m[c][row]
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) k[c][row] = float(v[3 * row + c]), r[c][row] = float(v[9 + 3 * row + c]);
    if (!(k[0][0] > 0.0f && k[1][1] > 0.0f && std::abs(k[2][2] - 1.0f) < 1e-3f)) throw Error(calibration.string() + ": intrinsics of " + name + " are not a camera's");
    if (std::abs(glm::determinant(r) - 1.0f) > 0.01f) throw Error(calibration.string() + ": rotation of " + name + " is not a rotation");
    // Camera centre C = -R^T t; the object sits where the cameras look, so the view direction
    // is minus the optical axis (R's third row), which needs no estimate of the object's centre.
    const glm::vec3 axis(r[0][2], r[1][2], r[2][2]);
    ring.names.push_back(name);
    ring.directions.push_back(-glm::normalize(axis));
    ring.cameras.push_back({k, r, glm::vec3(float(v[18]), float(v[19]), float(v[20]))});
  }
  return ring;
}

glm::mat3 fundamental_matrix(const RingCamera& from, const RingCamera& to) {
  // The motion from `from`'s frame to `to`'s: X_to = R X_from + t.
  const glm::mat3 r = to.r * glm::transpose(from.r);
  const glm::vec3 t = to.t - r * from.t;
  const glm::mat3 cross_t(0.0f, t.z, -t.y, -t.z, 0.0f, t.x, t.y, -t.x, 0.0f);  // columns of [t]x
  return glm::transpose(glm::inverse(to.k)) * cross_t * r * glm::inverse(from.k);
}

float epipolar_distance(const glm::mat3& fundamental, const glm::vec2& from_pixel, const glm::vec2& to_pixel) {
  const glm::vec3 line = fundamental * glm::vec3(from_pixel, 1.0f);
  const float norm = std::hypot(line.x, line.y);
  if (norm <= 0.0f) return 0.0f;  // no motion between the cameras: every match is consistent
  return std::abs(glm::dot(line, glm::vec3(to_pixel, 1.0f))) / norm;
}

glm::vec2 calibrated_pixel(const glm::vec2& stored, const glm::ivec2& size, int quarter_turns) {
  const float w = float(size.x - 1), h = float(size.y - 1);
  switch (quarter_turns & 3) {
    case 1: return {h - stored.y, stored.x};
    case 2: return {w - stored.x, h - stored.y};
    case 3: return {stored.y, w - stored.x};
    default: return stored;
  }
}

int stored_quarter_turns(const RingCamera& from, const RingCamera& to, const std::vector<std::pair<glm::vec2, glm::vec2>>& matches,
                         const glm::ivec2& size) {
  if (matches.empty()) return 0;
  const glm::mat3 f = fundamental_matrix(from, to);
  int best = 0;
  float best_median = std::numeric_limits<float>::max();
  for (int turns = 0; turns < 4; ++turns) {
    std::vector<float> d;
    for (const auto& [a, b] : matches)
      d.push_back(epipolar_distance(f, calibrated_pixel(a, size, turns), calibrated_pixel(b, size, turns)));
    const float median_distance = *median_in_place(std::span<float>(d));  // matches is not empty
    if (median_distance < best_median) best_median = median_distance, best = turns;
  }
  return best;
}

EpipolarCheck check_epipolar(const RingCamera& from, const RingCamera& to, const std::vector<std::pair<glm::vec2, glm::vec2>>& matches,
                             const glm::ivec2& size, float tolerance) {
  EpipolarCheck check;
  check.quarter_turns = stored_quarter_turns(from, to, matches, size);
  const glm::mat3 f = fundamental_matrix(from, to);
  for (const auto& [a, b] : matches)
    check.off_line += epipolar_distance(f, calibrated_pixel(a, size, check.quarter_turns), calibrated_pixel(b, size, check.quarter_turns)) > tolerance;
  return check;
}

std::vector<RingTriple> ring_triples(const PhotoRing& ring, float max_step_degrees) {
  std::vector<RingTriple> out;
  for (int i = 0; i + 2 < int(ring.names.size()); ++i) {
    const float a = degrees_between(ring.directions[size_t(i)], ring.directions[size_t(i + 1)]);
    const float b = degrees_between(ring.directions[size_t(i + 1)], ring.directions[size_t(i + 2)]);
    if (a > max_step_degrees || b > max_step_degrees || a + b < 0.1f) continue;
    out.push_back({i, i + 1, i + 2, a / (a + b)});
  }
  return out;
}

}  // namespace inkwire
