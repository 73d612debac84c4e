#pragma once
// The HTTP listener's pages: a session's page (its element full-size and the snippet that puts
// it on another page) at /scene/NAME, /turntable/NAME, /conference/NAME and /call/NAME, and the
// front page at /.
#include <optional>
#include <string>

namespace inkwire::server {

class Server;
struct Request;

// The page for `path` when it is a session page's address (a 404 naming what is missing when
// there is no such session), or nothing when it is none.
std::optional<std::string> session_page(Server& server, const Request& request, const std::string& path);
// The front page: what this server offers.
std::string front_page(Server& server);

}  // namespace inkwire::server
