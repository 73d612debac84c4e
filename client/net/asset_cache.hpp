#pragma once
// The client's asset cache (SPEC N2): files named by content hash, with the announced file
// name's extension so loaders know the format. A download in progress lives in `<hash>.partial`
// and resumes from its length; a finished one is checked against its hash before it is renamed
// into place, so a file under a hash name is always that content.
#include <filesystem>
#include <optional>

#include "protocol/messages.hpp"

namespace inkwire {

class AssetCache {
 public:
  // Creates the folder if needed; throws inkwire::Error if it cannot.
  explicit AssetCache(std::filesystem::path dir);

  // Where the asset lives once complete.
  std::filesystem::path path_of(const protocol::AssetAnnounce& asset) const;
  bool has(const protocol::AssetAnnounce& asset) const;
  // Bytes of a partial download already held (where to resume).
  uint64_t partial_size(const protocol::AssetAnnounce& asset) const;
  // Appends the next piece of a download; throws inkwire::Error if `offset` is not where the
  // partial file ends or the piece runs past the announced size.
  void append(const protocol::AssetAnnounce& asset, uint64_t offset, const protocol::Bytes& data);
  // Verifies a complete partial file and moves it into place; throws inkwire::Error (and drops
  // the partial file) if its hash differs.
  std::filesystem::path finish(const protocol::AssetAnnounce& asset);

  // The default cache folder: $XDG_CACHE_HOME/inkwire or ~/.cache/inkwire.
  static std::filesystem::path default_dir();

 private:
  std::filesystem::path partial_path(const protocol::AssetAnnounce& asset) const;
  std::filesystem::path dir_;
};

}  // namespace inkwire
