#pragma once
// Named style parameters ("--set KEY=VALUE", style-change messages). Each style declares its
// parameters with defaults; values are validated when set, so a renderer never sees junk.
#include <map>
#include <utility>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace inkwire {

enum class ParamType { Float, Int, Bool, Colour, Choice, Text };

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Float;
  std::string default_value;
  std::string help;
  double min = 0.0, max = 0.0;        // Float / Int range, inclusive
  std::vector<std::string> choices;   // Choice: the accepted values; Text: suggestions (any text is accepted)
  bool names_file = false;            // Text: a path to a file is accepted (a panel offers a path field)
};

ParamSpec float_param(std::string name, std::string default_value, double min, double max, std::string help);
ParamSpec int_param(std::string name, std::string default_value, double min, double max, std::string help);
ParamSpec bool_param(std::string name, std::string default_value, std::string help);
ParamSpec colour_param(std::string name, std::string default_value, std::string help);
// `suggestions`: values a user would usually pick (a panel offers them); any text is accepted.
ParamSpec text_param(std::string name, std::string default_value, std::string help, std::vector<std::string> suggestions = {});
// Text that names a file, or one of `suggestions` (shipped names).
ParamSpec file_param(std::string name, std::string default_value, std::string help, std::vector<std::string> suggestions = {});
ParamSpec choice_param(std::string name, std::string default_value, std::vector<std::string> choices, std::string help);
// A number as a parameter's value is written ("%g": 0.5, 12, 1e-06).
std::string param_number(double v);

class StyleParams {
 public:
  StyleParams() = default;
  explicit StyleParams(std::vector<ParamSpec> specs);

  // Throws inkwire::Error naming the key and the accepted values when either is wrong.
  void set(const std::string& key, const std::string& value);
  void set_assignment(const std::string& key_equals_value);

  float get_float(const std::string& key) const;
  int get_int(const std::string& key) const;
  bool get_bool(const std::string& key) const;
  glm::vec3 get_colour(const std::string& key) const;
  const std::string& get_text(const std::string& key) const;

  bool has(const std::string& key) const;
  const std::vector<ParamSpec>& specs() const { return specs_; }
  const std::map<std::string, std::string>& values() const { return values_; }

 private:
  const ParamSpec& spec(const std::string& key) const;
  std::vector<ParamSpec> specs_;
  std::map<std::string, std::string> values_;
};

// Splits "KEY=VALUE". Throws inkwire::Error when there is no '=' or no key.
std::pair<std::string, std::string> split_assignment(const std::string& key_equals_value);

// "#rrggbb" -> linear-ish 0..1 RGB. Throws inkwire::Error on anything else.
glm::vec3 parse_hex_colour(const std::string& text);

std::string to_string(ParamType type);

}  // namespace inkwire
