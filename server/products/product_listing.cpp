#include "server/products/product_listing.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/gzip.hpp"

namespace inkwire::server {
namespace {

// A file under its content hash: its manifest entry {"file", "sha256", "size"}.
nlohmann::json listed(ProductListing& listing, const protocol::Hash& hash, uint64_t size, const std::string& extension,
                      std::optional<protocol::Bytes> cell = std::nullopt) {
  const std::string hex = to_hex(hash);
  const std::string name = "files/" + hex + extension;
  const std::string type = extension == ".png" ? "image/png" : extension == ".jpg" ? "image/jpeg" : "application/octet-stream";
  listing.files[name] = ProductFile{hash, size, type, std::move(cell)};
  return {{"file", name}, {"sha256", hex}, {"size", size}};
}

std::string extension_of(const protocol::AssetAnnounce& asset) {
  const std::string ext = std::filesystem::path(asset.name).extension().string();
  return ext == ".png" ? ".png" : ".jpg";  // the store keeps photos as JPEG and mattes as PNG
}

}  // namespace

ProductListing product_listing(const protocol::Snapshot& state, const std::vector<protocol::TweenData>& cells) {
  if (state.kind != protocol::SessionKind::Turntable || state.product.directions.empty())
    throw Error("session '" + state.session + "' is no product");
  const protocol::Product& p = state.product;
  ProductListing listing;
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
    const nlohmann::json entry = listed(listing, asset.hash, asset.size, extension_of(asset));
    if (asset.kind == protocol::AssetKind::Samples) manifest["photos"].push_back(entry);
    else if (asset.kind == protocol::AssetKind::Matte) manifest["mattes"].push_back(entry);
    else if (asset.kind == protocol::AssetKind::Zoom) manifest["zoom"][zoom_seen++ / p.directions.size()].push_back(entry);
  }
  manifest["cells"] = nlohmann::json::array();
  for (const protocol::TweenData& cell : cells) {
    nlohmann::json entry = listed(listing, content_hash(cell.data.data(), cell.data.size()), cell.data.size(), ".cell", cell.data);
    entry["pair"] = cell.pair;
    manifest["cells"].push_back(entry);
  }
  listing.manifest = manifest.dump() + "\n";  // one line: the first view waits for it
  listing.manifest_gzipped = gzipped(listing.manifest);
  listing.etag = "\"" + to_hex(content_hash(listing.manifest.data(), listing.manifest.size())).substr(0, 32) + "\"";
  listing.first_view_bytes = listing.manifest.size() + manifest["photos"][0]["size"].get<uint64_t>() +
                             (manifest["mattes"].empty() ? 0 : manifest["mattes"][0]["size"].get<uint64_t>());
  return listing;
}

}  // namespace inkwire::server
