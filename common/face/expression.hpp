#pragma once
// Expression codes (SPEC F3): what the server sends for a face, one byte on the wire with an
// intensity 0-255 beside it. The numbers are part of the wire protocol: append, never renumber.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace inkwire {

enum class Expression : uint8_t {
  Neutral = 0,
  Smile = 1,
  Laugh = 2,
  Frown = 3,
  Surprise = 4,
  Sad = 5,
  EyesClosed = 6,
  WinkLeft = 7,   // the eye on the image's left is closed
  WinkRight = 8,
  VisemeClosed = 9,  // lips pressed (m, b, p)
  VisemeOpen = 10,   // jaw dropped (a)
  VisemeWide = 11,   // lips spread, slightly open (e, i)
  VisemeRound = 12,  // lips rounded, narrow (o, u)
};
constexpr int kExpressionCount = 13;

const char* name_of(Expression e);
std::optional<Expression> expression_from_name(std::string_view name);
// Codes from the wire: nothing for numbers this version does not know.
inline std::optional<Expression> expression_from_code(uint8_t code) {
  if (code >= kExpressionCount) return std::nullopt;
  return Expression(code);
}

// The layers a face is sent in (SPEC F21, common/face/face_layers.hpp) take only some codes: the
// expression layer no eyes-closed, winks or visemes (the eyes and the mouth are theirs), the mouth
// layer no eyes. Each eye's openness is a percentage of the neutral photo's, 0 (shut) to 200.
constexpr bool is_viseme(Expression e) { return e >= Expression::VisemeClosed && e <= Expression::VisemeRound; }
constexpr bool expression_layer_takes(Expression e) { return e <= Expression::Sad; }
constexpr bool mouth_layer_takes(Expression e) { return expression_layer_takes(e) || is_viseme(e); }
inline constexpr uint8_t kEyeOpen = 100;  // as in the neutral photo
inline constexpr uint8_t kMaxEyeOpenness = 200;

// An expression as the face shows it: which one, and how strongly (255 = the full template).
struct ExpressionState {
  Expression expression = Expression::Neutral;
  uint8_t intensity = 0;
  bool operator==(const ExpressionState&) const = default;
};

}  // namespace inkwire
