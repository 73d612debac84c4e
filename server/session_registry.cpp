#include "server/session_registry.hpp"

#include <set>

#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/model_bundle.hpp"
#include "server/products/product_store.hpp"
#include "server/session_token.hpp"

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;

protocol::AssetAnnounce add_session_asset(AssetStore& store, const SessionAsset& asset, UpAxis up) {
  return asset.kind == protocol::AssetKind::Mesh ? store_model(store, asset.path, up) : store.add_file(asset.path, asset.kind);
}

}  // namespace

// A mesh travels as one file: a model of several files (glTF with .bin and images, OBJ with
// .mtl), or one whose up axis clients would not find by themselves, is made into one Y-up GLB
// with everything inside, so every client gets it whole and upright.
protocol::AssetAnnounce store_model(AssetStore& store, const fs::path& file, UpAxis up) {
  if (const std::optional<SelfContainedModel> whole = self_contained_model(file, up)) {
    std::vector<std::string> gathered;
    for (const fs::path& p : whole->gathered) gathered.push_back(p.filename().string());
    log_info("model-made-whole", {{"path", file}, {"as", whole->name}, {"bytes", whole->bytes.size()}, {"files", gathered}});
    return store.add_bytes(whole->bytes, protocol::AssetKind::Mesh, whole->name);
  }
  return store.add_file(file, protocol::AssetKind::Mesh);
}

protocol::Snapshot fresh_session_state(const std::string& name, protocol::SessionKind kind, const std::string& style, const std::vector<std::string>& settings) {
  protocol::Snapshot state;
  state.session = name;
  state.kind = kind;
  state.style = {.renderer = style, .settings = settings};
  const Camera camera = scene_orbit_camera(30, 20, 1.4f);
  state.camera = {.sequence = 0, .position = camera.position, .target = camera.target, .up = camera.up, .fov_y_degrees = camera.fov_y_degrees};
  return state;
}

void SessionRegistry::load() {
  // Sessions in the catalogue come back as they were; configured ones it lacks are created.
  // Tokens are the config's to give: a configured session takes the config's tokens even when its
  // state comes from the catalogue (a changed editor token applies at the next start).
  for (StoredSession& stored : store_.sessions()) {
    const std::string name = stored.state.session;
    for (const SessionConfig& c : config_.sessions)
      if (c.name == name && (stored.token != hash_token(c.token) || stored.editor_token != hash_token(c.editor_token))) {
        stored.token = hash_token(c.token);
        stored.editor_token = hash_token(c.editor_token);
        store_.save_session(stored);
      }
    sessions_[name] = std::make_shared<Session>(std::move(stored));
  }
  for (const SessionConfig& c : config_.sessions) {
    if (sessions_.count(c.name)) continue;
    StoredSession stored{.token = hash_token(c.token), .editor_token = hash_token(c.editor_token), .state = {}};
    if (c.product) {
      try {
        stored.state = find_or_make_product(store_, *c.product, c.name, [&](int done, int total, const std::string& line) {
          log_info("product-pair", {{"session", c.name}, {"done", done}, {"total", total}, {"pair", line}});
        });
      } catch (const Error& e) {
        log(LogLevel::Error, "product-failed", {{"session", c.name}, {"source", c.product->describe()}, {"reason", e.what()}});
        continue;
      }
    }
    const protocol::Snapshot fresh = fresh_session_state(c.name, c.kind, c.style, c.settings);
    stored.state.session = fresh.session;
    stored.state.kind = fresh.kind;
    stored.state.style = fresh.style;
    stored.state.camera = fresh.camera;
    for (const SessionAsset& a : c.assets) stored.state.assets.push_back(add_session_asset(store_, a, c.up));
    store_.save_session(stored);
    log_info("session-created", {{"session", c.name}, {"kind", protocol::to_string(c.kind)}, {"assets", stored.state.assets.size()}});
    sessions_[c.name] = std::make_shared<Session>(std::move(stored));
  }
  sweep_unnamed_assets();
  for (auto& [name, session] : sessions_) ready_product(*session);
}

// A product is checked (every file against its hash) and its tween data readied once.
void SessionRegistry::ready_product(Session& session) {
  if (session.state().kind != protocol::SessionKind::Turntable || session.state().product.directions.empty()) return;
  try {
    session.set_product(product_tween_messages(store_, session.state()));
    log_info("product-loaded", {{"session", session.name()}, {"samples", session.state().product.directions.size()},
                                {"cells", session.state().product.cells}});
  } catch (const Error& e) {
    session.set_unavailable(e.what());
    log(LogLevel::Error, "product-unavailable", {{"session", session.name()}, {"reason", e.what()}});
  }
}

std::shared_ptr<Session> SessionRegistry::add(StoredSession stored) {
  if (sessions_.count(stored.state.session)) return nullptr;
  try {
    store_.save_session(stored);
  } catch (const Error& e) {
    log(LogLevel::Error, "session-not-added", {{"session", stored.state.session}, {"reason", e.what()}});
    return nullptr;
  }
  return serve(std::move(stored));
}

std::shared_ptr<Session> SessionRegistry::serve(StoredSession stored) {
  const std::string name = stored.state.session;
  auto session = std::make_shared<Session>(std::move(stored));
  ready_product(*session);
  sessions_[name] = session;
  if (on_added) on_added(*session);
  log_info("session-added", {{"session", name}, {"kind", protocol::to_string(session->state().kind)}, {"assets", session->state().assets.size()}});
  return session;
}

void SessionRegistry::sweep_unnamed_assets() {
  const AssetStore::Swept swept = store_.sweep_unnamed(std::chrono::seconds(int64_t(config_.asset_sweep_grace_seconds)));
  if (!swept.skipped.empty()) log_warn("asset-sweep-skipped", {{"reason", swept.skipped}});
  else log_info("assets-swept", {{"assets", swept.assets}, {"files", swept.files}, {"bytes", swept.bytes},
                                 {"grace_seconds", config_.asset_sweep_grace_seconds}});
}

// A product added while the server runs (`inkwire-server add-product` is a process of its own,
// writing the same catalogue): served from the next tick of the persist loop, under its name.
// A name the server already serves keeps its session until a restart. A product removed
// (`remove-product`) is no longer served from the same tick; other kinds of session stay.
void SessionRegistry::adopt_stored_elsewhere() {
  if (!store_.changed_elsewhere()) return;
  std::set<std::string> stored_names;
  for (StoredSession& stored : store_.sessions()) {
    stored_names.insert(stored.state.session);
    const auto served = sessions_.find(stored.state.session);
    if (served == sessions_.end()) serve(std::move(stored));  // already in the catalogue: not written again
    else if (stored.maker == MadeBy::Command && stored.state.assets != served->second->state().assets && !stored.state.assets.empty())
      served->second->replace_model(stored.state.assets.front());  // add-scene gave a served scene a new model
    else if (stored.kept && !served->second->stored().kept)
      served->second->keep();  // keep-scene: an uploaded scene the operator keeps
  }
  for (auto it = sessions_.begin(); it != sessions_.end();) {
    const bool removable = it->second->state().kind == protocol::SessionKind::Turntable || it->second->stored().maker != MadeBy::Operator;
    if (!removable || stored_names.count(it->first)) {
      ++it;
      continue;
    }
    const std::shared_ptr<Session> removed = it->second;
    it = sessions_.erase(it);
    const bool product = removed->state().kind == protocol::SessionKind::Turntable;
    log_info(product ? "product-removed" : "session-removed", {{"session", removed->name()}, {"members", removed->members()}});
    if (on_removed) on_removed(*removed);
  }
}

bool SessionRegistry::remove(const std::string& name) {
  const auto it = sessions_.find(name);
  if (it == sessions_.end()) return false;
  const std::shared_ptr<Session> removed = it->second;
  sessions_.erase(it);
  try {
    store_.remove_session(name);
  } catch (const Error& e) {
    log(LogLevel::Error, "session-not-removed", {{"session", name}, {"reason", e.what()}});
  }
  if (on_removed) on_removed(*removed);
  return true;
}

void SessionRegistry::persist(Session& session) {
  try {
    store_.save_session(session.stored());
    session.dirty = false;
  } catch (const Error& e) {
    log(LogLevel::Error, "persist-failed", {{"session", session.name()}, {"reason", e.what()}});
  }
}

std::shared_ptr<Session> SessionRegistry::find(const std::string& name) const {
  const auto it = sessions_.find(name);
  return it == sessions_.end() ? nullptr : it->second;
}

}  // namespace inkwire::server
