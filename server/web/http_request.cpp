#include "server/web/http_request.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "common/error.hpp"

namespace inkwire::server {
namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

}  // namespace

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

Request parse_head(const std::string& head) {
  std::istringstream lines(head);
  std::string line;
  std::getline(lines, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  Request r;
  std::istringstream first(line);
  std::string version;
  if (!(first >> r.method >> r.path >> version) || version.rfind("HTTP/1.", 0) != 0) throw Error("not an HTTP/1 request");
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) break;
    const size_t colon = line.find(':');
    if (colon == std::string::npos || colon == 0) throw Error("malformed header line");
    r.headers[lower(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }
  return r;
}

}  // namespace inkwire::server
