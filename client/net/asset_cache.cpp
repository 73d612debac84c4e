#include "client/net/asset_cache.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <utility>

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

AssetCache::Download::Download(const AssetCache& cache, const protocol::AssetAnnounce& asset, int fd) : cache_(&cache), asset_(asset), fd_(fd) {}

AssetCache::Download::Download(Download&& other) noexcept : cache_(other.cache_), asset_(std::move(other.asset_)), fd_(std::exchange(other.fd_, -1)) {}

AssetCache::Download::~Download() {
  if (fd_ >= 0) ::close(fd_);  // the lock goes with the descriptor
}

uint64_t AssetCache::Download::resume_at() const {
  struct stat s {};
  return ::fstat(fd_, &s) == 0 ? std::min<uint64_t>(uint64_t(s.st_size), asset_.size) : 0;
}

void AssetCache::Download::append(uint64_t offset, const protocol::Bytes& data) {
  if (offset != resume_at()) throw Error("asset chunk at " + std::to_string(offset) + " does not continue the download of " + asset_.name);
  if (offset + data.size() > asset_.size) throw Error("asset chunk runs past the announced size of " + asset_.name);
  for (size_t done = 0; done < data.size();) {
    const ssize_t n = ::pwrite(fd_, data.data() + done, data.size() - done, off_t(offset + done));
    if (n <= 0) throw Error("cannot write to the asset cache " + cache_->dir_.string() + ": " + std::strerror(errno));
    done += size_t(n);
  }
}

fs::path AssetCache::Download::finish() {
  const fs::path partial = cache_->partial_path(asset_), done = cache_->path_of(asset_);
  if (content_hash_of_file(partial) != asset_.hash) {
    fs::remove(partial);
    throw Error("download of " + asset_.name + " does not match its content hash");
  }
  // Renamed while locked: a download waiting for this one finds the file in place.
  fs::rename(partial, done);
  ::close(std::exchange(fd_, -1));
  return done;
}

std::optional<AssetCache::Download> AssetCache::begin(const protocol::AssetAnnounce& asset, std::chrono::milliseconds wait) const {
  const auto until = std::chrono::steady_clock::now() + wait;
  const fs::path partial = partial_path(asset);
  for (;;) {
    if (has(asset)) return std::nullopt;
    const int fd = ::open(partial.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw Error("cannot write to the asset cache " + dir_.string() + ": " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      // Another download may have finished between the look and the lock: its file is in place
      // and this partial file is one this download made empty.
      if (!has(asset)) return Download(*this, asset, fd);
      struct stat s {};
      if (::fstat(fd, &s) == 0 && s.st_size == 0 && s.st_nlink > 0) fs::remove(partial);
      ::close(fd);
      return std::nullopt;
    }
    ::close(fd);
    if (std::chrono::steady_clock::now() > until) throw Error("another download of " + asset.name + " did not end in time");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace inkwire
