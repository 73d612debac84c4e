#include "common/face/expression_templates.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <map>

#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace inkwire {

const std::map<std::string, std::string_view>& face_template_files();  // generated from common/face/*.json

namespace {

constexpr const char* kFormat = "inkwire-expression-templates";
constexpr int kVersion = 1;
constexpr float kMaxOffset = 2.0f;  // inter-ocular distances: no expression moves a point further

}  // namespace

ExpressionTemplates parse_templates(std::string_view json_text) {
  ExpressionTemplates out;
  try {
    const nlohmann::json j = nlohmann::json::parse(json_text);
    if (j.value("format", "") != kFormat) throw Error(std::string("expression templates: format is not '") + kFormat + "'");
    if (j.value("version", 0) != kVersion) throw Error("expression templates: version is not " + std::to_string(kVersion));
    out.made = j.value("made", "");
    for (const auto& [name, entry] : j.at("templates").items()) {
      const auto expression = expression_from_name(name);
      if (!expression) throw Error("expression templates: unknown expression '" + name + "'");
      const auto& points = entry.at("offsets");
      if (!points.is_array() || points.size() != kFaceLandmarks)
        throw Error("expression templates: '" + name + "' needs " + std::to_string(kFaceLandmarks) + " offsets");
      FaceLandmarks offsets;
      for (size_t i = 0; i < offsets.size(); ++i) {
        const auto& p = points.at(i);
        if (!p.is_array() || p.size() != 2) throw Error("expression templates: '" + name + "' offset " + std::to_string(i) + " is not [x, y]");
        offsets[i] = {p.at(0).get<float>(), p.at(1).get<float>()};
        if (!std::isfinite(offsets[i].x) || !std::isfinite(offsets[i].y) || std::abs(offsets[i].x) > kMaxOffset ||
            std::abs(offsets[i].y) > kMaxOffset)
          throw Error("expression templates: '" + name + "' offset " + std::to_string(i) + " is not finite or too large");
      }
      out.offsets[size_t(*expression)] = offsets;
      out.made_each[size_t(*expression)] = entry.value("made", "");
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("expression templates: ") + e.what());
  }
  out.offsets[size_t(Expression::Neutral)] = FaceLandmarks{};
  return out;
}

std::string templates_to_json(const ExpressionTemplates& templates) {
  // Written by hand so each template's 68 offsets sit on a line of their own (diffable).
  const auto quoted = [](const std::string& text) { return nlohmann::json(text).dump(); };
  std::ostringstream out;
  out << "{\n \"format\": " << quoted(kFormat) << ",\n \"version\": " << kVersion << ",\n"
      << " \"frame\": " << quoted("normalised face frame: origin between the eye centres, x along the eye line, y down, "
                                  "unit = inter-ocular distance; left and right as in the image") << ",\n"
      << " \"made\": " << quoted(templates.made) << ",\n \"templates\": {";
  const char* separator = "\n";
  for (int e = 1; e < kExpressionCount; ++e) {
    if (!templates.offsets[size_t(e)]) continue;
    out << separator << "  " << quoted(name_of(Expression(e))) << ": {\"made\": " << quoted(templates.made_each[size_t(e)])
        << ",\n   \"offsets\": [";
    char number[64];
    for (size_t i = 0; i < kFaceLandmarks; ++i) {
      const glm::vec2 p = (*templates.offsets[size_t(e)])[i];
      std::snprintf(number, sizeof number, "%s[%.4f,%.4f]", i ? "," : "", double(p.x), double(p.y));
      out << number;
    }
    out << "]}";
    separator = ",\n";
  }
  out << "\n }\n}\n";
  return out.str();
}

const ExpressionTemplates& shipped_templates() {
  static const ExpressionTemplates templates = parse_templates(face_template_files().at("expression_templates.json"));
  return templates;
}

FaceLandmarks apply_expression(const FaceLandmarks& neutral, const ExpressionTemplates& templates, ExpressionState state) {
  const auto& offsets = templates.offsets[size_t(state.expression)];
  if (!offsets) return neutral;
  const FaceFrame frame = face_frame(neutral);
  const float amount = float(state.intensity) / 255.0f;
  FaceLandmarks out = neutral;
  for (size_t i = 0; i < out.size(); ++i) out[i] += frame.offset_to_image(amount * (*offsets)[i]);
  return out;
}

}  // namespace inkwire
