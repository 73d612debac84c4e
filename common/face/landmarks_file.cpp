#include "common/face/landmarks_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace inkwire {
namespace {

constexpr const char* kFormat = "inkwire-face-landmarks";
constexpr std::uintmax_t kMaxFileBytes = 64 << 10;  // 68 points need about 2 KB
constexpr float kMaxCoordinate = 1e6f;

}  // namespace

std::string landmarks_to_json(const FaceLandmarks& landmarks) {
  nlohmann::json points = nlohmann::json::array();
  for (const glm::vec2& p : landmarks) points.push_back({p.x, p.y});
  return nlohmann::json{{"format", kFormat}, {"points", points}}.dump();
}

FaceLandmarks parse_landmarks(const std::string& json) {
  const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw Error("landmarks: not a JSON object");
  const auto format = j.find("format");
  if (format == j.end() || !format->is_string() || format->get<std::string>() != kFormat) throw Error(std::string("landmarks: format is not '") + kFormat + "'");
  const auto points = j.find("points");
  if (points == j.end() || !points->is_array() || points->size() != kFaceLandmarks)
    throw Error("landmarks: 'points' must hold " + std::to_string(kFaceLandmarks) + " [x, y] pairs");
  FaceLandmarks landmarks;
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const nlohmann::json& p = (*points)[i];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw Error("landmarks: point " + std::to_string(i) + " is not [x, y]");
    landmarks[i] = {p[0].get<float>(), p[1].get<float>()};
    if (!std::isfinite(landmarks[i].x) || !std::isfinite(landmarks[i].y) || std::abs(landmarks[i].x) > kMaxCoordinate ||
        std::abs(landmarks[i].y) > kMaxCoordinate)
      throw Error("landmarks: point " + std::to_string(i) + " is out of range");
  }
  return landmarks;
}

void save_landmarks(const std::filesystem::path& file, const FaceLandmarks& landmarks) {
  const std::filesystem::path partial = file.string() + ".partial";
  {
    std::ofstream out(partial);
    out << landmarks_to_json(landmarks) << "\n";
    if (!out) throw Error("cannot write landmarks '" + partial.string() + "'");
  }
  std::error_code ec;
  std::filesystem::rename(partial, file, ec);
  if (ec) throw Error("cannot write landmarks '" + file.string() + "': " + ec.message());
}

FaceLandmarks load_landmarks(const std::filesystem::path& file) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  if (ec) throw Error("cannot read landmarks '" + file.string() + "': " + ec.message());
  if (bytes > kMaxFileBytes) throw Error("landmarks '" + file.string() + "': larger than 64 KB");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) throw Error("cannot read landmarks '" + file.string() + "'");
  try {
    return parse_landmarks(text.str());
  } catch (const Error& e) {
    throw Error(file.filename().string() + ": " + e.what());
  }
}

}  // namespace inkwire
