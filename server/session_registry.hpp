#pragma once
// The sessions this instance serves, by name, and what keeps them in the catalogue: those the
// catalogue holds come back as they were, configured ones it lacks are made (a product's photos
// or mesh included), others are added later (from another instance, or stored by another process
// such as add-product), and changed state is written back. Each product is checked and readied
// once; assets nothing names are swept at load. Touched on the I/O thread only.
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "server/asset_store.hpp"
#include "server/config.hpp"
#include "server/session.hpp"

namespace inkwire::server {

// A new session's state: its name, kind and style, and the camera every scene starts from.
protocol::Snapshot fresh_session_state(const std::string& name, protocol::SessionKind kind, const std::string& style,
                                       const std::vector<std::string>& settings = {});
// A model file stored as a scene's mesh asset: made into one Y-up GLB with everything inside when
// it is several files or says another up axis (common/model_bundle.hpp), else as it is. Throws
// inkwire::Error with the reason for a model no client could draw, storing nothing.
protocol::AssetAnnounce store_model(AssetStore& store, const std::filesystem::path& file, UpAxis up);

class SessionRegistry {
 public:
  SessionRegistry(AssetStore& store, const ServerConfig& config) : store_(store), config_(config) {}

  void load();
  std::shared_ptr<Session> find(const std::string& name) const;
  const std::map<std::string, std::shared_ptr<Session>>& all() const { return sessions_; }
  // A session defined elsewhere (another instance, another process): stored and served. Null if
  // a session of that name exists or it cannot be stored.
  std::shared_ptr<Session> add(StoredSession stored);
  // What another process changed since the last look: products stored (add-product while the
  // server runs) are added, products taken out (remove-product) are dropped.
  void adopt_stored_elsewhere();
  void persist(Session& session);
  // Session `name` served no more and taken out of the catalogue (a room gone, a scene expired
  // or removed), announced to on_removed; false when there is none.
  bool remove(const std::string& name);
  // Called for each session added after load() (the server starts a conference's call).
  std::function<void(Session&)> on_added;
  // Called for each session dropped while the server runs, after it left the registry (the
  // server ends its members' connections).
  std::function<void(Session&)> on_removed;

 private:
  // A session of the catalogue served from now on (readied, announced to on_added).
  std::shared_ptr<Session> serve(StoredSession stored);
  void ready_product(Session& session);
  void sweep_unnamed_assets();

  AssetStore& store_;
  const ServerConfig& config_;
  std::map<std::string, std::shared_ptr<Session>> sessions_;
};

}  // namespace inkwire::server
