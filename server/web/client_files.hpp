#pragma once
// The browser client's files as the HTTP listener serves them: the element scripts and their
// modules (/inkwire.js, /elements/..., embedded at build time, web_files.hpp), the tween shaders
// (/shaders/tween/...), and the renderer compiled to WebAssembly (/module/inkwire-scene.js and
// .wasm, which the build leaves beside the binary in web/). Every one may be read by pages of
// any origin: a shop's, a course's or a community's page embeds the elements from here.
#include <optional>
#include <string>

namespace inkwire::server {

struct Request;

// The reply for `path` when it names one of those files (a 404 for a module file this build
// lacks), or nothing when it names none.
std::optional<std::string> client_file_reply(const Request& request, const std::string& path);

}  // namespace inkwire::server
