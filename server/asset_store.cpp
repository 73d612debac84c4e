#include "server/asset_store.hpp"

#include <ctime>
#include <set>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include <fstream>

#include <sqlite3.h>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "server/session_token.hpp"

namespace inkwire::server {
namespace fs = std::filesystem;
using protocol::AssetAnnounce;

namespace {

// A prepared statement that finalises itself.
class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) throw Error(std::string("catalogue: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& text) {
    sqlite3_bind_text(stmt_, i, text.data(), int(text.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Statement& bind(int i, int64_t value) {
    sqlite3_bind_int64(stmt_, i, value);
    return *this;
  }
  Statement& bind_blob(int i, const protocol::Bytes& bytes) {
    sqlite3_bind_blob(stmt_, i, bytes.data(), int(bytes.size()), SQLITE_TRANSIENT);
    return *this;
  }
  // True while there is a row to read.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) throw Error(std::string("catalogue: ") + sqlite3_errmsg(db_));
    return false;
  }
  std::string text(int column) const {
    const auto* p = sqlite3_column_text(stmt_, column);
    return p ? std::string(reinterpret_cast<const char*>(p), size_t(sqlite3_column_bytes(stmt_, column))) : std::string();
  }
  int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
  protocol::Bytes blob(int column) const {
    const auto* p = static_cast<const uint8_t*>(sqlite3_column_blob(stmt_, column));
    return p ? protocol::Bytes(p, p + sqlite3_column_bytes(stmt_, column)) : protocol::Bytes();
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// A state is a snapshot frame: read back through the same validating decoder as the wire.
protocol::Snapshot decode_snapshot_frame(const protocol::Bytes& frame) {
  if (frame.size() < protocol::kHeaderBytes) throw Error("no state stored");
  const auto header = protocol::parse_header(frame.data());
  auto message = protocol::decode(header.type, frame.data() + protocol::kHeaderBytes, frame.size() - protocol::kHeaderBytes);
  auto* snapshot = std::get_if<protocol::Snapshot>(&message);
  if (!snapshot) throw Error("stored state is not a snapshot");
  return std::move(*snapshot);
}

// States stored by protocol version 3 end before the product's zoom levels (version 4): read as
// none, so a server upgraded in place keeps its sessions.
protocol::Snapshot decode_state(const protocol::Bytes& frame) {
  try {
    return decode_snapshot_frame(frame);
  } catch (const protocol::ProtocolError& e) {
    protocol::Bytes with_levels = frame;
    with_levels.insert(with_levels.end(), {0, 0});
    const uint32_t length = uint32_t(with_levels.size() - protocol::kHeaderBytes);
    for (int k = 0; k < 4; ++k) with_levels[size_t(k)] = uint8_t(length >> (8 * k));
    try {
      return decode_snapshot_frame(with_levels);
    } catch (const protocol::ProtocolError&) {
      throw e;
    }
  }
}

// Flushes a file (or a folder's entries) to the disk, so a crash right after cannot leave a
// named asset whose bytes never reached it.
void sync_to_disk(const fs::path& path, bool folder) {
  const int fd = ::open(path.c_str(), (folder ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot open '" + path.string() + "' to flush it");
  const int rc = ::fsync(fd);
  ::close(fd);
  if (rc != 0) throw Error("cannot flush '" + path.string() + "' to disk");
}

// Renames a fully written and flushed `partial` to `target` and flushes the folder's entry.
void name_durably(const fs::path& partial, const fs::path& target, const std::string& what) {
  std::error_code ec;
  sync_to_disk(partial, false);
  fs::rename(partial, target, ec);
  if (ec) throw Error("cannot store asset '" + what + "': " + ec.message());
  sync_to_disk(target.parent_path(), true);
}

}  // namespace

AssetStore::AssetStore(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  fs::create_directories(dir_ / "assets", ec);
  if (ec) throw Error("cannot create data folder '" + dir_.string() + "': " + ec.message());
  const fs::path catalogue = dir_ / "catalogue.sqlite";
  if (sqlite3_open_v2(catalogue.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
    const std::string reason = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw Error("cannot open catalogue '" + catalogue.string() + "': " + reason);
  }
  sqlite3_busy_timeout(db_, 2000);
  exec("PRAGMA journal_mode=WAL");
  exec("PRAGMA synchronous=NORMAL");
  exec("CREATE TABLE IF NOT EXISTS assets (hash TEXT PRIMARY KEY, size INTEGER NOT NULL, kind INTEGER NOT NULL, "
       "name TEXT NOT NULL, added TEXT NOT NULL DEFAULT CURRENT_TIMESTAMP)");
  exec("CREATE TABLE IF NOT EXISTS products (key TEXT PRIMARY KEY, state BLOB NOT NULL, "
       "added TEXT NOT NULL DEFAULT CURRENT_TIMESTAMP)");
  exec("CREATE TABLE IF NOT EXISTS sessions (name TEXT PRIMARY KEY, kind TEXT NOT NULL, token TEXT NOT NULL, "
       "state BLOB NOT NULL, updated TEXT NOT NULL DEFAULT CURRENT_TIMESTAMP)");
  // Catalogues from before editor tokens gain the column (a session without one has no editors).
  bool has_editor_token = false;
  for (Statement q(db_, "PRAGMA table_info(sessions)"); q.step();) has_editor_token |= q.text(1) == "editor_token";
  if (!has_editor_token) exec("ALTER TABLE sessions ADD COLUMN editor_token TEXT NOT NULL DEFAULT ''");
  // ... and, from before sessions people make, who made each (the operator, for those before).
  bool has_maker = false;
  for (Statement q(db_, "PRAGMA table_info(sessions)"); q.step();) has_maker |= q.text(1) == "made_by";
  if (!has_maker) {
    exec("ALTER TABLE sessions ADD COLUMN made_by TEXT NOT NULL DEFAULT 'operator'");
    exec("ALTER TABLE sessions ADD COLUMN creator TEXT NOT NULL DEFAULT ''");
    exec("ALTER TABLE sessions ADD COLUMN kept INTEGER NOT NULL DEFAULT 0");
  }
  changed_elsewhere();  // from here on, what other processes write is noticed
}

AssetStore::~AssetStore() { sqlite3_close(db_); }

void AssetStore::exec(const char* sql) const {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string reason = message ? message : "unknown error";
    sqlite3_free(message);
    throw Error("catalogue: " + reason);
  }
}

fs::path AssetStore::asset_path(const protocol::Hash& hash) const { return dir_ / "assets" / to_hex(hash); }

AssetAnnounce AssetStore::add_file(const fs::path& source, protocol::AssetKind kind, std::string name) {
  std::error_code ec;
  if (fs::is_directory(source, ec)) throw Error("asset '" + source.string() + "' is a folder, not a file");
  const auto size = fs::file_size(source, ec);
  if (ec) throw Error("cannot read asset '" + source.string() + "': " + ec.message());
  if (size > protocol::kMaxAssetBytes) throw Error("asset '" + source.string() + "' is larger than 1 GiB");
  AssetAnnounce announce{.hash = content_hash_of_file(source), .size = size, .kind = kind,
                         .name = name.empty() ? source.filename().string() : name};
  const fs::path target = asset_path(announce.hash);
  if (!fs::exists(target)) {
    // Copy under a temporary name and rename, so a crash never leaves a half file under a hash.
    const fs::path partial = target.string() + ".partial";
    fs::copy_file(source, partial, fs::copy_options::overwrite_existing, ec);
    if (ec) throw Error("cannot store asset '" + source.string() + "': " + ec.message());
    name_durably(partial, target, source.string());
  }
  Statement(db_, "INSERT OR REPLACE INTO assets (hash, size, kind, name) VALUES (?, ?, ?, ?)")
      .bind(1, to_hex(announce.hash)).bind(2, int64_t(size)).bind(3, int64_t(kind)).bind(4, announce.name).step();
  return announce;
}

AssetAnnounce AssetStore::add_bytes(const protocol::Bytes& bytes, protocol::AssetKind kind, const std::string& name) {
  if (bytes.size() > protocol::kMaxAssetBytes) throw Error("asset '" + name + "' is larger than 1 GiB");
  AssetAnnounce announce{.hash = content_hash(bytes.data(), bytes.size()), .size = bytes.size(), .kind = kind, .name = name};
  const fs::path target = asset_path(announce.hash);
  if (!fs::exists(target)) {
    const fs::path partial = target.string() + ".partial";
    {
      std::ofstream out(partial, std::ios::binary | std::ios::trunc);
      out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      if (!out) throw Error("cannot store asset '" + name + "': write failed");
    }
    name_durably(partial, target, name);
  }
  Statement(db_, "INSERT OR REPLACE INTO assets (hash, size, kind, name) VALUES (?, ?, ?, ?)")
      .bind(1, to_hex(announce.hash)).bind(2, int64_t(bytes.size())).bind(3, int64_t(kind)).bind(4, name).step();
  return announce;
}

protocol::Bytes AssetStore::read_verified(const protocol::Hash& hash) const {
  const auto announce = find(hash);
  if (!announce) throw Error("no asset " + to_hex(hash));
  std::ifstream in(asset_path(hash), std::ios::binary);
  if (!in) throw Error("asset file of " + announce->name + " is missing from the store");
  protocol::Bytes bytes(size_t(announce->size));
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (size_t(in.gcount()) != bytes.size() || in.peek() != EOF)
    throw Error("asset file of " + announce->name + " is not the size catalogued");
  if (content_hash(bytes.data(), bytes.size()) != hash)
    throw Error("asset file of " + announce->name + " does not match its hash (corrupted)");
  return bytes;
}

std::optional<AssetAnnounce> AssetStore::find(const protocol::Hash& hash) const {
  Statement q(db_, "SELECT size, kind, name FROM assets WHERE hash = ?");
  q.bind(1, to_hex(hash));
  if (!q.step()) return std::nullopt;
  return AssetAnnounce{.hash = hash, .size = uint64_t(q.integer(0)), .kind = protocol::AssetKind(q.integer(1)), .name = q.text(2)};
}

protocol::Bytes AssetStore::read(const protocol::Hash& hash, uint64_t offset, uint32_t length) const {
  const auto announce = find(hash);
  if (!announce) throw Error("no asset " + to_hex(hash));
  // Checked whole against its hash before its first byte is served, and again whenever the
  // file has been written since: a corrupted file is refused, never sent.
  std::error_code ec;
  const auto written = fs::last_write_time(asset_path(hash), ec);
  if (ec) throw Error("asset file of " + announce->name + " is missing from the store");
  if (const auto it = verified_.find(hash); it == verified_.end() || it->second != written) {
    try {
      read_verified(hash);
    } catch (const Error& e) {
      log(LogLevel::Error, "asset-corrupted", {{"asset", announce->name}, {"hash", to_hex(hash)}, {"reason", e.what()}});
      throw;
    }
    verified_[hash] = written;
  }
  if (offset > announce->size) throw Error("offset " + std::to_string(offset) + " is past the end of asset " + announce->name);
  std::ifstream in(asset_path(hash), std::ios::binary);
  if (!in) throw Error("asset file of " + announce->name + " is missing from the store");
  protocol::Bytes bytes(size_t(std::min<uint64_t>(length, announce->size - offset)));
  in.seekg(std::streamoff(offset));
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()));
  if (size_t(in.gcount()) != bytes.size()) throw Error("asset file of " + announce->name + " is shorter than catalogued");
  return bytes;
}

AssetStore::Swept AssetStore::sweep_unnamed(std::chrono::seconds grace, std::chrono::system_clock::time_point now) {
  Swept out;
  std::set<std::string> named;
  for (const char* table : {"sessions", "products"})
    for (Statement q(db_, (std::string("SELECT state FROM ") + table).c_str()); q.step();) {
      try {
        for (const auto& a : decode_state(q.blob(0)).assets) named.insert(to_hex(a.hash));
      } catch (const Error& e) {
        out.skipped = std::string("a stored ") + (table[0] == 's' ? "session" : "product") + " state is unreadable (" + e.what() + ")";
        return out;
      }
    }
  // The cutoff as the catalogue writes its times (CURRENT_TIMESTAMP: UTC, whole seconds).
  const std::time_t cutoff_time = std::chrono::system_clock::to_time_t(now - grace);
  std::tm cutoff_tm{};
  gmtime_r(&cutoff_time, &cutoff_tm);
  char cutoff[32];
  std::strftime(cutoff, sizeof cutoff, "%Y-%m-%d %H:%M:%S", &cutoff_tm);
  std::vector<std::pair<std::string, uint64_t>> unnamed;
  std::set<std::string> catalogued;
  Statement q(db_, "SELECT hash, size, added < ? FROM assets");
  q.bind(1, std::string(cutoff));
  while (q.step()) {
    catalogued.insert(q.text(0));
    if (q.integer(2) && !named.count(q.text(0))) unnamed.push_back({q.text(0), uint64_t(q.integer(1))});
  }
  for (const auto& [hex, size] : unnamed) {
    Statement(db_, "DELETE FROM assets WHERE hash = ?").bind(1, hex).step();
    std::error_code ec;
    if (fs::remove(dir_ / "assets" / hex, ec)) ++out.files;
    ++out.assets, out.bytes += size;
  }
  // Files the catalogue does not name, as old: never renamed into place, or never catalogued.
  const auto too_old = fs::file_time_type::clock::from_sys(now - grace);
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir_ / "assets", ec)) {
    const std::string name = entry.path().filename().string();
    const std::string hex = name.substr(0, name.find('.'));
    std::error_code file_ec;
    if (catalogued.count(hex) && !name.ends_with(".partial")) continue;
    if (entry.last_write_time(file_ec) > too_old || file_ec) continue;
    const uint64_t size = entry.file_size(file_ec);
    if (fs::remove(entry.path(), file_ec)) ++out.files, out.bytes += size;
  }
  return out;
}

bool AssetStore::changed_elsewhere() {
  Statement q(db_, "PRAGMA data_version");
  const int64_t version = q.step() ? q.integer(0) : data_version_;
  const int64_t before = std::exchange(data_version_, version);
  return before >= 0 && before != version;
}

std::vector<StoredSession> AssetStore::sessions() const {
  std::vector<StoredSession> out;
  Statement q(db_, "SELECT name, token, editor_token, state, made_by, creator, kept FROM sessions ORDER BY name");
  while (q.step()) {
    try {
      out.push_back({.token = as_token_hash(q.text(1)), .editor_token = as_token_hash(q.text(2)), .state = decode_state(q.blob(3)),
                     .maker = made_by_from_string(q.text(4)), .creator = q.text(5), .kept = q.integer(6) != 0});
    } catch (const Error& e) {
      log_warn("session-state-unreadable", {{"session", q.text(0)}, {"reason", e.what()}});
    }
  }
  return out;
}

void AssetStore::save_product(const std::string& key, const protocol::Snapshot& state) {
  Statement(db_, "INSERT OR REPLACE INTO products (key, state) VALUES (?, ?)").bind(1, key).bind_blob(2, protocol::encode(state)).step();
}

std::optional<protocol::Snapshot> AssetStore::find_product(const std::string& key) const {
  Statement q(db_, "SELECT state FROM products WHERE key = ?");
  q.bind(1, key);
  if (!q.step()) return std::nullopt;
  try {
    return decode_state(q.blob(0));
  } catch (const Error&) {
    return std::nullopt;  // from an older version: made again
  }
}

bool AssetStore::remove_product(const std::string& name) {
  Statement kind(db_, "SELECT kind FROM sessions WHERE name = ?");
  kind.bind(1, name);
  if (!kind.step() || kind.text(0) != protocol::to_string(protocol::SessionKind::Turntable)) return false;
  std::vector<std::string> made;
  for (Statement q(db_, "SELECT key, state FROM products"); q.step();) {
    try {
      if (decode_state(q.blob(1)).session == name) made.push_back(q.text(0));
    } catch (const Error&) {
      // a record from an older version: not this product's to remove
    }
  }
  exec("BEGIN IMMEDIATE");
  try {
    Statement(db_, "DELETE FROM sessions WHERE name = ?").bind(1, name).step();
    for (const std::string& key : made) Statement(db_, "DELETE FROM products WHERE key = ?").bind(1, key).step();
    exec("COMMIT");
  } catch (...) {
    exec("ROLLBACK");
    throw;
  }
  return true;
}

bool AssetStore::remove_session(const std::string& name) {
  Statement find(db_, "SELECT name FROM sessions WHERE name = ?");
  find.bind(1, name);
  if (!find.step()) return false;
  Statement(db_, "DELETE FROM sessions WHERE name = ?").bind(1, name).step();
  return true;
}

void AssetStore::save_session(const StoredSession& session) {
  Statement(db_, "INSERT OR REPLACE INTO sessions (name, kind, token, editor_token, state, made_by, creator, kept, updated) "
                 "VALUES (?, ?, ?, ?, ?, ?, ?, ?, CURRENT_TIMESTAMP)")
      .bind(1, session.state.session).bind(2, protocol::to_string(session.state.kind)).bind(3, session.token)
      .bind(4, session.editor_token).bind_blob(5, protocol::encode(session.state)).bind(6, to_string(session.maker))
      .bind(7, session.creator).bind(8, int64_t(session.kept)).step();
}

}  // namespace inkwire::server
