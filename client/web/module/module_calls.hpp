#pragma once
// What every class the module gives JavaScript shares: a call that never throws into the page
// (it returns "" or the one-line reason), and a style's settings as the page passes them.
#include <exception>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/error.hpp"

namespace inkwire {

// Runs `action`; "" when it succeeded, else what went wrong, in one line.
template <class Action>
std::string guarded(Action action) {
  try {
    action();
    return "";
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("unexpected: ") + e.what();
  }
}

// A JSON list of "KEY=VALUE" strings, as the session's style carries them.
inline std::vector<std::string> settings_of(const std::string& settings_json) {
  std::vector<std::string> settings;
  for (const auto& s : nlohmann::json::parse(settings_json)) settings.push_back(s.get<std::string>());
  return settings;
}

}  // namespace inkwire
