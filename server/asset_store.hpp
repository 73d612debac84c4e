#pragma once
// The server's embedded store (SPEC N2): asset files named by content hash under DIR/assets,
// and a SQLite catalogue DIR/catalogue.sqlite of assets and sessions (kind, token, last state).
// Created on first use; survives a killed server (files are renamed into place before the
// catalogue names them, flushed to disk first; SQLite runs in WAL mode). Not thread-safe: the server uses it from its
// one I/O thread.
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "protocol/messages.hpp"
#include "server/stored_session.hpp"

struct sqlite3;

namespace inkwire::server {

class AssetStore {
 public:
  // Throws inkwire::Error if the folder or catalogue cannot be created or opened.
  explicit AssetStore(const std::filesystem::path& dir);
  ~AssetStore();
  AssetStore(const AssetStore&) = delete;
  AssetStore& operator=(const AssetStore&) = delete;

  // Copies a file into the store (once per content) and catalogues it under `name` (default:
  // the file's name). Throws inkwire::Error if it cannot be read or is over the size limit.
  protocol::AssetAnnounce add_file(const std::filesystem::path& source, protocol::AssetKind kind, std::string name = "");
  // The same for bytes in memory.
  protocol::AssetAnnounce add_bytes(const protocol::Bytes& bytes, protocol::AssetKind kind, const std::string& name);
  std::optional<protocol::AssetAnnounce> find(const protocol::Hash& hash) const;
  // The whole asset, read back and checked against its hash. Throws inkwire::Error if it is
  // unknown, missing, or its bytes are no longer what was stored (a corrupted file).
  protocol::Bytes read_verified(const protocol::Hash& hash) const;
  // Up to `length` bytes at `offset` (fewer at the end). The whole file is checked against its
  // hash before it is first served and whenever it changed since. Throws inkwire::Error if the
  // asset is unknown, its file is missing or corrupted, or the offset is past its end.
  protocol::Bytes read(const protocol::Hash& hash, uint64_t offset, uint32_t length) const;

  // Sessions whose stored state this version cannot read (an older protocol) are left out and
  // logged, so the configured defaults take their place.
  std::vector<StoredSession> sessions() const;
  void save_session(const StoredSession& session);

  // Products by key (product_store.hpp): the state of a session that shows the product.
  void save_product(const std::string& key, const protocol::Snapshot& state);
  std::optional<protocol::Snapshot> find_product(const std::string& key) const;
  // Takes product session `name` out of the catalogue, with the made-product records stored
  // under that name, so its assets are named no more (swept after the grace period at a start)
  // and a running server drops it. False when the catalogue has no product of that name.
  bool remove_product(const std::string& name);
  // Takes session `name` out of the catalogue whatever its kind (a room gone, a scene removed);
  // false when there is none.
  bool remove_session(const std::string& name);

  // Assets no session and no product names, stored more than `grace` ago: what an add-product
  // killed half-way leaves (its files are written before the product that names them). Their
  // rows and files go, and so do files of the same age the catalogue never named (a crash between
  // the rename and the row, an unfinished .partial). A catalogue holding a state this version
  // cannot read sweeps nothing (what it names is unknown), and says so in `skipped`.
  struct Swept {
    size_t assets = 0, files = 0;
    uint64_t bytes = 0;
    std::string skipped;
  };
  // `now` is when the sweep counts from (a test's own clock; the real one otherwise).
  Swept sweep_unnamed(std::chrono::seconds grace, std::chrono::system_clock::time_point now = std::chrono::system_clock::now());

  // Whether another process (add-product, while the server runs) wrote the catalogue since the
  // last call: SQLite's data_version, which this connection's own writes leave alone.
  bool changed_elsewhere();

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path asset_path(const protocol::Hash& hash) const;
  void exec(const char* sql) const;
  std::filesystem::path dir_;
  sqlite3* db_ = nullptr;
  int64_t data_version_ = -1;
  mutable std::map<protocol::Hash, std::filesystem::file_time_type> verified_;  // and when its file was written
};

}  // namespace inkwire::server
