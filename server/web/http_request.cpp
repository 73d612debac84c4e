#include "server/web/http_request.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string_view>

#include "common/error.hpp"

namespace inkwire::server {
namespace {

// RFC 9110 5.6.2: a field name is a token.
bool is_token(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
    return std::isalnum(c) || std::string_view("!#$%&'*+-.^_`|~").find(char(c)) != std::string_view::npos;
  });
}

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
    const std::string name = line.substr(0, colon), value = trim(line.substr(colon + 1));
    if (!is_token(name)) throw Error("malformed header name");
    if (std::any_of(value.begin(), value.end(), [](unsigned char c) { return (c < 0x20 && c != '\t') || c == 0x7f; }))
      throw Error("control character in header " + lower(name));
    // A header given twice would be read as one or the other by different readers (a proxy and
    // this server): refused, not guessed.
    if (!r.headers.emplace(lower(name), value).second) throw Error("header " + lower(name) + " given twice");
  }
  return r;
}

std::string query_value(const std::string& target, const std::string& name) {
  const size_t query = target.find('?');
  if (query == std::string::npos) return "";
  std::istringstream parts(target.substr(query + 1));
  for (std::string part; std::getline(parts, part, '&');) {
    if (part.rfind(name + "=", 0) != 0) continue;
    std::string value;
    for (size_t i = name.size() + 1; i < part.size(); ++i) {
      if (part[i] == '+') value += ' ';
      else if (part[i] != '%') value += part[i];
      else if (i + 2 < part.size() && std::isxdigit(static_cast<unsigned char>(part[i + 1])) && std::isxdigit(static_cast<unsigned char>(part[i + 2]))) {
        value += char(std::stoi(part.substr(i + 1, 2), nullptr, 16));
        i += 2;
      } else {
        return "";
      }
    }
    return value;
  }
  return "";
}

}  // namespace inkwire::server
