#include "server/web/http_reply.hpp"

namespace inkwire::server {

const std::string kAnyOrigin = "Access-Control-Allow-Origin: *\r\n";
const std::string kEmbeddable = "Cross-Origin-Embedder-Policy: require-corp\r\nCross-Origin-Resource-Policy: cross-origin\r\n" + kAnyOrigin;
const std::string kIsolatedPage = "Cross-Origin-Opener-Policy: same-origin\r\nCross-Origin-Embedder-Policy: require-corp\r\n";

const char* status_reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 201: return "Created";
    case 204: return "No Content";
    case 303: return "See Other";
    case 304: return "Not Modified";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 409: return "Conflict";
    case 411: return "Length Required";
    case 413: return "Content Too Large";
    case 415: return "Unsupported Media Type";
    case 422: return "Unprocessable Content";
    case 429: return "Too Many Requests";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    case 503: return "Service Unavailable";
    default: return "Unknown";
  }
}

std::string http_reply(int status, const std::string& type, const std::string& body, const std::string& headers, const std::string& cache) {
  return "HTTP/1.1 " + std::to_string(status) + " " + status_reason(status) + "\r\nContent-Type: " + type +
         "\r\nContent-Length: " + std::to_string(body.size()) + "\r\nCache-Control: " + cache + "\r\nConnection: close\r\n" + headers + "\r\n" + body;
}

std::string text_reply(int status, const std::string& text, const std::string& headers) {
  return http_reply(status, "text/plain", text + "\n", headers);
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : c == '\'' ? "&#39;" : std::string(1, c);
  return out;
}

}  // namespace inkwire::server
