#pragma once
// The client's asset cache (SPEC N2): files named by content hash, with the announced file
// name's extension so loaders know the format. A download in progress lives in `<hash>.partial`
// and resumes from its length; a finished one is checked against its hash before it is renamed
// into place, so a file under a hash name is always that content. One download of an asset at a
// time, whoever asks: a download holds a lock on its partial file (flock), so a second asker in
// this process or in another sharing the folder waits for it and takes its file.
#include <chrono>
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

  // The download of one asset, alone with its partial file while it lives.
  class Download {
   public:
    Download(Download&& other) noexcept;
    Download& operator=(Download&&) = delete;
    ~Download();
    // Bytes already held (where to resume).
    uint64_t resume_at() const;
    // Appends the next piece; throws inkwire::Error if `offset` is not where the partial file
    // ends or the piece runs past the announced size.
    void append(uint64_t offset, const protocol::Bytes& data);
    // Verifies the complete file and moves it into place; throws inkwire::Error (and drops the
    // partial file) if its hash differs.
    std::filesystem::path finish();

   private:
    friend class AssetCache;
    Download(const AssetCache& cache, const protocol::AssetAnnounce& asset, int fd);
    const AssetCache* cache_;
    protocol::AssetAnnounce asset_;
    int fd_ = -1;
  };

  // Starts (or resumes) downloading `asset`, after waiting up to `wait` for another download of
  // it to end; nothing when the asset is complete by then (another download finished it).
  // Throws inkwire::Error when the folder cannot be written or the other download does not end.
  std::optional<Download> begin(const protocol::AssetAnnounce& asset, std::chrono::milliseconds wait = std::chrono::seconds(60)) const;

  // The default cache folder: $XDG_CACHE_HOME/inkwire or ~/.cache/inkwire.
  static std::filesystem::path default_dir();

 private:
  std::filesystem::path partial_path(const protocol::AssetAnnounce& asset) const;
  std::filesystem::path dir_;
};

}  // namespace inkwire
