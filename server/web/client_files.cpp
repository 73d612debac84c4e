#include "server/web/client_files.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>

#include "server/web/http_reply.hpp"
#include "server/web/http_request.hpp"
#include "server/web/web_files.hpp"

namespace inkwire::server {
namespace {

std::string content_type(const std::string& path) {
  if (path.ends_with(".js")) return "text/javascript; charset=utf-8";
  if (path.ends_with(".wasm")) return "application/wasm";
  if (path.ends_with(".json")) return "application/json";
  if (path.ends_with(".css")) return "text/css; charset=utf-8";
  if (path.ends_with(".jpg")) return "image/jpeg";
  return "text/plain; charset=utf-8";  // shaders
}

// A module file, read once, plain and gzipped. Null when this build has none.
struct ModuleFile {
  std::string plain, gzipped;
};
const ModuleFile* module_file(const std::string& name) {
  static std::mutex guard;
  static std::map<std::string, std::optional<ModuleFile>> cache;
  if (name != "inkwire-scene.js" && name != "inkwire-scene.wasm") return nullptr;
  const std::lock_guard lock(guard);
  auto [it, fresh] = cache.try_emplace(name);
  if (fresh) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / "web";
    const auto read = [](const std::filesystem::path& file) {
      std::ifstream in(file, std::ios::binary);
      return in ? std::optional<std::string>(std::string(std::istreambuf_iterator<char>(in), {})) : std::nullopt;
    };
    const std::optional<std::string> plain = read(dir / name), gzipped = read(dir / (name + ".gz"));
    if (plain && gzipped) it->second = ModuleFile{*plain, *gzipped};
  }
  return it->second ? &*it->second : nullptr;
}

}  // namespace

std::optional<std::string> client_file_reply(const Request& request, const std::string& path) {
  if (path.size() <= 1) return std::nullopt;
  for (const auto* files : {&web_client_files(), &web_shader_files()})
    if (const auto file = files->find(path.substr(1)); file != files->end())
      return http_reply(200, content_type(path), std::string(file->second), kEmbeddable);
  if (const auto file = web_page_files().find(path.substr(1)); file != web_page_files().end())
    return http_reply(200, content_type(path), std::string(file->second), "", "no-cache");
  if (!path.starts_with("/module/")) return std::nullopt;
  const std::string name = path.substr(8);
  const ModuleFile* file = module_file(name);
  if (!file) return text_reply(404, "no module file " + name + " (this server was built without the browser's renderer)", kAnyOrigin);
  // Sent compressed to browsers that take it (every one does): the size a page really loads.
  const bool gzip = request.header("accept-encoding").find("gzip") != std::string::npos;
  return http_reply(200, content_type(path), gzip ? file->gzipped : file->plain,
                    (gzip ? "Content-Encoding: gzip\r\nVary: Accept-Encoding\r\n" : "") + kEmbeddable, "no-cache");
}

}  // namespace inkwire::server
