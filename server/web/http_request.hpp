#pragma once
// An HTTP/1.x request head as the HTTP listener reads it (server/web/http_server.cpp): the
// method, the path and the headers. The head comes from anyone: it is bounded by the listener
// (8 KiB) and parsed here without trusting a byte of it (tests/fuzz/fuzz_http.cpp).
#include <map>
#include <string>

namespace inkwire::server {

struct Request {
  std::string method, path;
  std::map<std::string, std::string> headers;  // names in lower case
  std::string header(const std::string& name) const {
    const auto it = headers.find(name);
    return it == headers.end() ? "" : it->second;
  }
};

// Throws inkwire::Error for a head that is not HTTP/1.x, a header name that is no token, a
// control character in a value, or a header given twice.
Request parse_head(const std::string& head);
// The value of `name` in the target's query (`/path?a=1&name=value`), percent-decoded; empty when
// absent or malformed.
std::string query_value(const std::string& target, const std::string& name);
// ASCII lower case, as header names and upgrade tokens compare.
std::string lower(std::string s);

}  // namespace inkwire::server
