#include "server/tween/photo_ring.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "common/error.hpp"

namespace inkwire {
namespace {

float degrees_between(const glm::vec3& a, const glm::vec3& b) {
  return float(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / 3.14159265358979);
}

}  // namespace

PhotoRing load_photo_ring(const std::filesystem::path& folder) {
  std::filesystem::path calibration;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.path().filename().string().ends_with("_par.txt")) calibration = entry.path();
  if (calibration.empty()) throw Error(folder.string() + ": no *_par.txt calibration file (Middlebury ring layout)");
  std::ifstream in(calibration);
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
    glm::mat3 r;  // rows of R in the file: glm is column-major, so r[c][row]
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 3; ++c) r[c][row] = float(v[9 + 3 * row + c]);
    if (std::abs(glm::determinant(r) - 1.0f) > 0.01f) throw Error(calibration.string() + ": rotation of " + name + " is not a rotation");
    // Camera centre C = -R^T t; the object sits where the cameras look, so the view direction
    // is minus the optical axis (R's third row), which needs no estimate of the object's centre.
    const glm::vec3 axis(r[0][2], r[1][2], r[2][2]);
    ring.names.push_back(name);
    ring.directions.push_back(-glm::normalize(axis));
  }
  return ring;
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
