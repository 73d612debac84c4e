#pragma once
// Structured logs: one JSON object per line on stderr, e.g.
//   {"t":"2026-11-21T10:00:00.123Z","level":"info","event":"join","session":"demo","client":3}
// so logs can be grepped by people and parsed by scripts. Thread-safe.
#include <string>

#include <nlohmann/json.hpp>

namespace inkwire {

enum class LogLevel { Debug, Info, Warn, Error };

void set_log_level(LogLevel level);
void log(LogLevel level, const std::string& event, nlohmann::json fields = nlohmann::json::object());

inline void log_info(const std::string& event, nlohmann::json fields = nlohmann::json::object()) {
  log(LogLevel::Info, event, std::move(fields));
}
inline void log_warn(const std::string& event, nlohmann::json fields = nlohmann::json::object()) {
  log(LogLevel::Warn, event, std::move(fields));
}

}  // namespace inkwire
