#pragma once
// What the tests of sessions people make share (SPEC N6-N11): uploads over plain HTTP as a
// browser's FormData sends them, the server's answer taken apart, /metrics figures by name, and
// what the data folder holds.
#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "e2e_support.hpp"

namespace inkwire::e2e {

// An HTTP answer taken apart: status, headers (names in lower case) and body.
struct HttpAnswer {
  int status = 0;
  std::map<std::string, std::string> headers;
  std::string body, raw;
  // The body's JSON ({"error": ...} or the made scene), or null.
  nlohmann::json json() const { return nlohmann::json::parse(body, nullptr, false); }
  std::string error() const {
    const auto j = json();
    return j.is_object() ? j.value("error", "") : "";
  }
};

inline HttpAnswer parse_answer(const std::string& raw) {
  HttpAnswer a;
  a.raw = raw;
  const size_t end = raw.find("\r\n\r\n");
  if (raw.rfind("HTTP/1.1 ", 0) != 0 || end == std::string::npos) return a;
  a.status = std::atoi(raw.c_str() + 9);
  std::istringstream head(raw.substr(0, end));
  std::string line;
  std::getline(head, line);
  while (std::getline(head, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    a.headers[name] = line.substr(line.find_first_not_of(' ', colon + 1));
  }
  a.body = raw.substr(end + 4);
  return a;
}

inline std::string read_file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A multipart/form-data body of `files` (each part named by its file's own name), as a page's
// FormData of picked files is sent.
inline const std::string kBoundary = "----inkwire-e2e-7d3f9a";
inline std::string multipart_body(const std::vector<std::pair<std::string, std::string>>& named_bytes) {
  std::string body;
  for (const auto& [name, bytes] : named_bytes)
    body += "--" + kBoundary + "\r\nContent-Disposition: form-data; name=\"files\"; filename=\"" + name +
            "\"\r\nContent-Type: application/octet-stream\r\n\r\n" + bytes + "\r\n";
  return body + "--" + kBoundary + "--\r\n";
}
inline std::string multipart_of_files(const std::vector<fs::path>& files) {
  std::vector<std::pair<std::string, std::string>> parts;
  for (const fs::path& f : files) parts.emplace_back(f.filename().string(), read_file_bytes(f));
  return multipart_body(parts);
}

// POST `body` to `target` (/scenes, /scenes/NAME/model) with `headers` (each ending in CRLF).
inline HttpAnswer post_upload(int port, const std::string& body, const std::string& target = "/scenes", const std::string& headers = "") {
  return parse_answer(http_get(port, "POST " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
                                         "\r\nContent-Type: multipart/form-data; boundary=" + kBoundary + "\r\nContent-Length: " +
                                         std::to_string(body.size()) + "\r\n" + headers + "\r\n" + body));
}
inline HttpAnswer upload_files(int port, const std::vector<fs::path>& files, const std::string& target = "/scenes", const std::string& headers = "") {
  return post_upload(port, multipart_of_files(files), target, headers);
}

// The value of the sample `name` (with its labels, as /metrics writes it: `a_total{reason="x"}`),
// or -1 when /metrics has none.
inline double metric_value(const std::string& metrics, const std::string& name) {
  std::istringstream lines(metrics);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(name + " ", 0) == 0) return std::atof(line.c_str() + name.size() + 1);
  return -1;
}

// The regular files under `dir` (none when it is missing).
inline size_t files_under(const fs::path& dir) {
  size_t n = 0;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return 0;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file(ec)) ++n;
  return n;
}

// Lines of the server's log with event `event` whose "session" is `session`.
inline size_t events_for(ServerUnderTest& server, const std::string& event, const std::string& session) {
  size_t n = 0;
  for (const auto& j : log_events(server.process().output(), event)) n += j.value("session", "") == session;
  return n;
}

// A native member in a call: headless, five frames a second for up to ten minutes (stopped by the
// test), its frame log listing the members it shows. It shows its neutral photo (a window shows a
// call's grid once some member has a face or publishes).
inline std::unique_ptr<Process> native_member(const ServerUnderTest& server, const std::string& room, const fs::path& dir, const std::string& name,
                                       std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"--connect", server.address(), "--session", room, "--headless", "--frames", "3000", "--fps", "5",
                                "--size", "160x120", "--cache", (dir / ("cache-" + name)).string(), "--out",
                                (dir / (name + "-%04d.png")).string(), "--frame-log", (dir / (name + ".jsonl")).string(), "--name", name,
                                "--photo", kDlibPhoto.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return std::make_unique<Process>("inkwire-client", args, dir / (name + ".log"));
}

// The member names of the newest line of a native member's frame log.
inline std::set<std::string> shown_members(const fs::path& dir, const std::string& name) {
  const auto log = frame_log(dir / (name + ".jsonl"));
  std::set<std::string> names;
  if (!log.empty() && log.back().contains("members"))
    for (const auto& m : log.back()["members"]) names.insert(m.value("name", ""));
  return names;
}

}  // namespace inkwire::e2e
