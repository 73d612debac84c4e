#include "client/net/asset_cache.hpp"

#include <cstdlib>
#include <fstream>

#include "common/content_hash.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace fs = std::filesystem;

AssetCache::AssetCache(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw Error("cannot create asset cache '" + dir_.string() + "': " + ec.message());
}

fs::path AssetCache::default_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "inkwire";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "inkwire";
  return "inkwire-cache";
}

fs::path AssetCache::path_of(const protocol::AssetAnnounce& asset) const {
  // The announced name is a plain file name (checked by the protocol): only its extension is used.
  return dir_ / (to_hex(asset.hash) + fs::path(asset.name).extension().string());
}

fs::path AssetCache::partial_path(const protocol::AssetAnnounce& asset) const { return dir_ / (to_hex(asset.hash) + ".partial"); }

bool AssetCache::has(const protocol::AssetAnnounce& asset) const {
  std::error_code ec;
  return fs::file_size(path_of(asset), ec) == asset.size && !ec;
}

uint64_t AssetCache::partial_size(const protocol::AssetAnnounce& asset) const {
  std::error_code ec;
  const auto size = fs::file_size(partial_path(asset), ec);
  return ec ? 0 : std::min<uint64_t>(size, asset.size);
}

void AssetCache::append(const protocol::AssetAnnounce& asset, uint64_t offset, const protocol::Bytes& data) {
  if (offset != partial_size(asset)) throw Error("asset chunk at " + std::to_string(offset) + " does not continue the download of " + asset.name);
  if (offset + data.size() > asset.size) throw Error("asset chunk runs past the announced size of " + asset.name);
  std::ofstream out(partial_path(asset), std::ios::binary | std::ios::app);
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  if (!out) throw Error("cannot write to the asset cache " + dir_.string());
}

fs::path AssetCache::finish(const protocol::AssetAnnounce& asset) {
  const fs::path partial = partial_path(asset);
  if (content_hash_of_file(partial) != asset.hash) {
    fs::remove(partial);
    throw Error("download of " + asset.name + " does not match its content hash");
  }
  fs::rename(partial, path_of(asset));
  return path_of(asset);
}

}  // namespace inkwire
