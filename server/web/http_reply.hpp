#pragma once
// The HTTP listener's replies (server/web/http_server.cpp): one request per connection, so each
// reply is a whole HTTP/1.1 message with its length, closing the connection. The header sets
// below say who may read or embed what a reply carries.
#include <string>

namespace inkwire::server {

// Extra header lines, each ending in CRLF.
//   kAnyOrigin: pages of any origin may read the reply (a shop's page reading a product, the
//     element's scripts and module imported by a page elsewhere: module scripts are always
//     fetched in CORS mode).
//   kEmbeddable: a cross-origin isolated page (a call's, COEP require-corp) may load it, and a
//     worker's own script carries COEP itself, as Chromium asks; readable by any origin too.
//   kIsolatedPage: the page is cross-origin isolated (COOP and COEP), so a call's worker and
//     audio worklets can share rings of sound (SharedArrayBuffer) instead of messages that some
//     engines route past the page's thread.
extern const std::string kAnyOrigin, kEmbeddable, kIsolatedPage;

// A reply of `status` with `body` of content `type`; `cache` is its Cache-Control.
std::string http_reply(int status, const std::string& type, const std::string& body, const std::string& headers = "",
                       const std::string& cache = "no-store");
// A plain-text reply of one line (`text`, a line feed added): errors and refusals.
std::string text_reply(int status, const std::string& text, const std::string& headers = "");
// The reason phrase of the status codes the listener sends ("OK", "Not Found", ...).
const char* status_reason(int status);
// `s` safe inside HTML text and attribute values.
std::string html_escape(const std::string& s);

}  // namespace inkwire::server
