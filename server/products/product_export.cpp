#include "server/products/product_export.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "server/products/product_store.hpp"
#include "server/web/web_files.hpp"

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;

// Writes `bytes` to `path` through a .partial and a rename; a file already holding exactly
// these bytes is kept. True when it was written.
bool write_file(const fs::path& path, std::string_view bytes, ExportSummary& summary) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == bytes.size()) {
    std::ifstream in(path, std::ios::binary);
    std::string old(bytes.size(), '\0');
    if (in.read(old.data(), std::streamsize(old.size())) && old == bytes) {
      ++summary.kept;
      return false;
    }
  }
  fs::create_directories(path.parent_path(), ec);
  const fs::path partial = path.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw Error("cannot write '" + partial.string() + "'");
  }
  fs::rename(partial, path, ec);
  if (ec) throw Error("cannot write '" + path.string() + "': " + ec.message());
  ++summary.written;
  summary.bytes_written += bytes.size();
  return true;
}

std::string_view as_text(const protocol::Bytes& b) { return {reinterpret_cast<const char*>(b.data()), b.size()}; }

// One file of the product under its content hash `hash` (of `bytes`): {"file", "sha256", "size"}.
nlohmann::json put(const fs::path& dir, const protocol::Bytes& bytes, const ContentHash& hash, const std::string& extension, ExportSummary& summary) {
  const std::string hex = to_hex(hash);
  const std::string name = "files/" + hex + extension;
  write_file(dir / name, as_text(bytes), summary);
  return {{"file", name}, {"sha256", hex}, {"size", bytes.size()}};
}

std::string extension_of(const protocol::AssetAnnounce& asset) {
  const std::string ext = fs::path(asset.name).extension().string();
  return ext == ".png" ? ".png" : ".jpg";  // the store keeps photos as JPEG and mattes as PNG
}

}  // namespace

ExportSummary export_product(const AssetStore& store, const protocol::Snapshot& state, const fs::path& dir) {
  if (state.kind != protocol::SessionKind::Turntable || state.product.directions.empty())
    throw Error("session '" + state.session + "' is no product");
  const protocol::Product& p = state.product;
  ExportSummary summary;
  // The tween cells as a member receives them; every stored file is checked on the way.
  const std::vector<protocol::TweenData> cells = product_tween_messages(store, state);

  nlohmann::json manifest = {{"format", "inkwire-product"}, {"version", kProductManifestVersion}, {"name", state.session},
                             {"width", p.width}, {"height", p.height}, {"distance_diagonals", p.distance_diagonals},
                             {"fov_y_degrees", p.fov_y_degrees}};
  manifest["directions"] = nlohmann::json::array();
  for (const glm::vec3& d : p.directions) manifest["directions"].push_back({d.x, d.y, d.z});
  manifest["levels"] = nlohmann::json::array();
  for (const auto& l : p.levels) manifest["levels"].push_back({{"width", l.width}, {"height", l.height}});
  manifest["photos"] = manifest["mattes"] = nlohmann::json::array();
  manifest["zoom"] = nlohmann::json::array();
  for (size_t l = 0; l < p.levels.size(); ++l) manifest["zoom"].push_back(nlohmann::json::array());
  size_t zoom_seen = 0;
  for (const auto& asset : state.assets) {
    if (asset.kind == protocol::AssetKind::Tween) continue;  // as cells, below
    const protocol::Bytes bytes = store.read_verified(asset.hash);  // checked against the hash it is named by
    nlohmann::json entry = put(dir, bytes, asset.hash, extension_of(asset), summary);
    if (asset.kind == protocol::AssetKind::Samples) manifest["photos"].push_back(entry);
    else if (asset.kind == protocol::AssetKind::Matte) manifest["mattes"].push_back(entry);
    else if (asset.kind == protocol::AssetKind::Zoom) manifest["zoom"][zoom_seen++ / p.directions.size()].push_back(entry);
  }
  manifest["cells"] = nlohmann::json::array();
  for (const protocol::TweenData& cell : cells) {
    nlohmann::json entry = put(dir, cell.data, content_hash(cell.data.data(), cell.data.size()), ".cell", summary);
    entry["pair"] = cell.pair;
    manifest["cells"].push_back(entry);
  }
  // The element itself: its scripts and shaders at the paths they import each other by.
  for (const auto* files : {&web_client_files(), &web_shader_files()})
    for (const auto& [path, bytes] : *files) write_file(dir / path, bytes, summary);
  // The manifest last: until it is renamed into place, visitors read the previous one.
  const std::string text = manifest.dump() + "\n";  // one line: the first view waits for it
  write_file(dir / "product.json", text, summary);
  summary.first_view_bytes = text.size() + manifest["photos"][0]["size"].get<uint64_t>() +
                             (manifest["mattes"].empty() ? 0 : manifest["mattes"][0]["size"].get<uint64_t>());
  return summary;
}

}  // namespace inkwire::server
