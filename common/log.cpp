#include "common/log.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <mutex>

namespace inkwire {
namespace {

std::mutex log_mutex;
LogLevel minimum_level = LogLevel::Info;

std::string utc_now() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto millis = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                tm.tm_hour, tm.tm_min, tm.tm_sec, int(millis));
  return text;
}

}  // namespace

void set_log_level(LogLevel level) {
  std::lock_guard lock(log_mutex);
  minimum_level = level;
}

void log(LogLevel level, const std::string& event, nlohmann::json fields) {
  static const char* names[] = {"debug", "info", "warn", "error"};
  nlohmann::json line = {{"t", utc_now()}, {"level", names[int(level)]}, {"event", event}};
  if (fields.is_object()) line.update(fields);
  // Replace invalid UTF-8 (e.g. from a peer's text) instead of throwing.
  const std::string text = line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::lock_guard lock(log_mutex);
  if (level < minimum_level) return;
  std::fprintf(stderr, "%s\n", text.c_str());
  std::fflush(stderr);
}

}  // namespace inkwire
