#include "common/face/expression.hpp"

#include <array>

namespace inkwire {

namespace {

constexpr std::array<const char*, kExpressionCount> kNames = {
    "neutral",   "smile",     "laugh",         "frown",         "surprise",    "sad",         "eyes-closed",
    "wink-left", "wink-right", "viseme-closed", "viseme-open", "viseme-wide", "viseme-round"};

}  // namespace

const char* name_of(Expression e) { return kNames.at(size_t(e)); }

std::optional<Expression> expression_from_name(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (name == kNames[i]) return Expression(i);
  return std::nullopt;
}

}  // namespace inkwire
