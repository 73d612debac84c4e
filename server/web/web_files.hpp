#pragma once
// The browser client's files, embedded in the server at build time (server/CMakeLists.txt): the
// scripts of client/web/ by their path there (inkwire.js, elements/turntable.js, ...) and the
// tween shaders as shaders/tween/blend.vert and .frag. Served by the HTTP listener and written
// into a product's export (products/product_export.hpp).
#include <map>
#include <string>
#include <string_view>

namespace inkwire {  // where cmake/embed_files_script.cmake defines them

const std::map<std::string, std::string_view>& web_client_files();
const std::map<std::string, std::string_view>& web_shader_files();
// The server's own pages' files, by their path under client/web/ (pages/front.js, pages/call.jpg, ...).
const std::map<std::string, std::string_view>& web_page_files();

}  // namespace inkwire
