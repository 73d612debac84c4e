#pragma once
// Expression templates (SPEC F5): for each expression, how far every landmark moves from the
// neutral face at full intensity, in the normalised face frame. The client moves a neutral
// photo's landmarks by a template and warps the photo to match. The shipped set lives in
// common/face/expression_templates.json; how it was made is written in the file itself.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "common/face/expression.hpp"
#include "common/face/face_shape.hpp"

namespace inkwire {

struct ExpressionTemplates {
  std::string made;  // how the set was made, for people reading the file
  // Displacements per expression at intensity 255; Neutral is all zero. An expression without
  // a template shows as neutral.
  std::array<std::optional<FaceLandmarks>, kExpressionCount> offsets;
  std::array<std::string, kExpressionCount> made_each;
};

// Parses the JSON format; throws inkwire::Error with a one-line reason on anything malformed
// (wrong counts, non-finite or absurd displacements, unknown expression names).
ExpressionTemplates parse_templates(std::string_view json_text);
std::string templates_to_json(const ExpressionTemplates& templates);
// The set shipped with the product (embedded at build time).
const ExpressionTemplates& shipped_templates();

// The neutral face's landmarks (image pixels) moved to `state`.
FaceLandmarks apply_expression(const FaceLandmarks& neutral, const ExpressionTemplates& templates, ExpressionState state);

}  // namespace inkwire
