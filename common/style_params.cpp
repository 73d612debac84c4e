#include "common/style_params.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <type_traits>

#include "common/error.hpp"

namespace inkwire {
namespace {

template <typename T>
bool parse_number(const std::string& text, T& out) {
  if constexpr (std::is_floating_point_v<T>) {
    // The WebAssembly build's C++ library (libc++ 14) has no from_chars for floating point:
    // strtod, held to what from_chars takes (a digit, '-' or '.' first, no hex) and finite.
    if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' || text[0] == '.') ||
        text.find_first_of("xXpP") != std::string::npos)
      return false;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value)) return false;
    out = T(value);
    return true;
  } else {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
  }
}

bool parse_bool(const std::string& text, bool& out) {
  if (text == "1" || text == "true" || text == "on" || text == "yes") return out = true, true;
  if (text == "0" || text == "false" || text == "off" || text == "no") return out = false, true;
  return false;
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : "|") + i;
  return s;
}

}  // namespace

std::string param_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

ParamSpec float_param(std::string name, std::string def, double min, double max, std::string help) {
  return {std::move(name), ParamType::Float, std::move(def), std::move(help), min, max, {}};
}
ParamSpec int_param(std::string name, std::string def, double min, double max, std::string help) {
  return {std::move(name), ParamType::Int, std::move(def), std::move(help), min, max, {}};
}
ParamSpec bool_param(std::string name, std::string def, std::string help) {
  return {std::move(name), ParamType::Bool, std::move(def), std::move(help), 0, 0, {}};
}
ParamSpec colour_param(std::string name, std::string def, std::string help) {
  return {std::move(name), ParamType::Colour, std::move(def), std::move(help), 0, 0, {}};
}
ParamSpec text_param(std::string name, std::string def, std::string help, std::vector<std::string> suggestions) {
  return {std::move(name), ParamType::Text, std::move(def), std::move(help), 0, 0, std::move(suggestions)};
}
ParamSpec file_param(std::string name, std::string def, std::string help, std::vector<std::string> suggestions) {
  ParamSpec spec = text_param(std::move(name), std::move(def), std::move(help), std::move(suggestions));
  spec.names_file = true;
  return spec;
}
ParamSpec choice_param(std::string name, std::string def, std::vector<std::string> choices, std::string help) {
  return {std::move(name), ParamType::Choice, std::move(def), std::move(help), 0, 0, std::move(choices)};
}

std::string to_string(ParamType type) {
  switch (type) {
    case ParamType::Float: return "float";
    case ParamType::Int: return "int";
    case ParamType::Bool: return "bool";
    case ParamType::Colour: return "colour";
    case ParamType::Choice: return "choice";
    case ParamType::Text: return "text";
  }
  return "?";
}

glm::vec3 parse_hex_colour(const std::string& text) {
  if (text.size() != 7 || text[0] != '#') throw Error("colour '" + text + "' is not of the form #rrggbb");
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) {
    unsigned v = 0;
    auto [ptr, ec] = std::from_chars(text.data() + 1 + 2 * i, text.data() + 3 + 2 * i, v, 16);
    if (ec != std::errc() || ptr != text.data() + 3 + 2 * i) throw Error("colour '" + text + "' is not of the form #rrggbb");
    c[i] = float(v) / 255.0f;
  }
  return c;
}

StyleParams::StyleParams(std::vector<ParamSpec> specs) : specs_(std::move(specs)) {
  for (const ParamSpec& s : specs_) set(s.name, s.default_value);
}

const ParamSpec& StyleParams::spec(const std::string& key) const {
  for (const ParamSpec& s : specs_)
    if (s.name == key) return s;
  std::vector<std::string> names;
  for (const ParamSpec& s : specs_) names.push_back(s.name);
  throw Error("unknown parameter '" + key + "'" + (names.empty() ? " (this style has none)" : " (known: " + join(names) + ")"));
}

bool StyleParams::has(const std::string& key) const {
  return std::any_of(specs_.begin(), specs_.end(), [&](const ParamSpec& s) { return s.name == key; });
}

void StyleParams::set(const std::string& key, const std::string& value) {
  const ParamSpec& s = spec(key);
  const std::string bad = "parameter '" + key + "' = '" + value + "': ";
  switch (s.type) {
    case ParamType::Float: {
      double v;
      if (!parse_number(value, v) || !std::isfinite(v)) throw Error(bad + "not a number");
      if (v < s.min || v > s.max) throw Error(bad + "outside " + param_number(s.min) + ".." + param_number(s.max));
      break;
    }
    case ParamType::Int: {
      long v;
      if (!parse_number(value, v)) throw Error(bad + "not an integer");
      if (v < s.min || v > s.max) throw Error(bad + "outside " + param_number(s.min) + ".." + param_number(s.max));
      break;
    }
    case ParamType::Bool: {
      bool v;
      if (!parse_bool(value, v)) throw Error(bad + "expected true or false");
      break;
    }
    case ParamType::Colour: parse_hex_colour(value); break;
    case ParamType::Choice:
      if (std::find(s.choices.begin(), s.choices.end(), value) == s.choices.end())
        throw Error(bad + "expected one of " + join(s.choices));
      break;
    case ParamType::Text: break;
  }
  values_[key] = value;
}

std::pair<std::string, std::string> split_assignment(const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw Error("'" + kv + "' is not of the form KEY=VALUE");
  return {kv.substr(0, eq), kv.substr(eq + 1)};
}

void StyleParams::set_assignment(const std::string& kv) {
  const auto [key, value] = split_assignment(kv);
  set(key, value);
}

float StyleParams::get_float(const std::string& key) const {
  spec(key);
  double v = 0;
  parse_number(values_.at(key), v);
  return float(v);
}

int StyleParams::get_int(const std::string& key) const {
  spec(key);
  long v = 0;
  parse_number(values_.at(key), v);
  return int(v);
}

bool StyleParams::get_bool(const std::string& key) const {
  spec(key);
  bool v = false;
  parse_bool(values_.at(key), v);
  return v;
}

glm::vec3 StyleParams::get_colour(const std::string& key) const {
  spec(key);
  return parse_hex_colour(values_.at(key));
}

const std::string& StyleParams::get_text(const std::string& key) const {
  spec(key);
  return values_.at(key);
}

}  // namespace inkwire
