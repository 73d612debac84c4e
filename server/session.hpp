#pragma once
// One session ("room", SPEC N1/N4): its current state as a snapshot, its members, and the rule
// that a change by one member is applied, counted and forwarded to all the others.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "protocol/messages.hpp"
#include "server/asset_store.hpp"
#include "server/authority.hpp"
#include "server/call/call.hpp"
#include "server/products/product_listing.hpp"
#include "server/session_token.hpp"

namespace inkwire::server {

class Connection;

class Session {
 public:
  explicit Session(StoredSession stored) : stored_(std::move(stored)) {}

  const std::string& name() const { return stored_.state.session; }
  // The role a join's token gives (an editor, a visitor), or nothing for a wrong token.
  std::optional<Role> role_of(const std::string& token) const { return server::role_of(stored_.token, stored_.editor_token, token); }
  SessionAuthority authority() const { return {.kind = stored_.state.kind, .has_editor_token = !stored_.editor_token.empty()}; }
  const protocol::Snapshot& state() const { return stored_.state; }
  const StoredSession& stored() const { return stored_; }
  const protocol::AssetAnnounce* find_asset(const protocol::Hash& hash) const;  // null unless listed

  void join(const std::shared_ptr<Connection>& member);
  void leave(const Connection* member);
  // Ends every member's connection with `code` and `reason` (the session is no longer served).
  void close_members(protocol::ErrorCode code, const std::string& reason);
  size_t members() const { return members_.size(); }
  // ... and, in a call, its members on other instances (through the broker).
  size_t members_everywhere() const;

  // Applies a state message (style, camera, object, expression) from the member with
  // connection id `sender` (0: none), bumps the revision and forwards it, encoded once, to every
  // other member. False if it is no change. Called by the relay (server/relay/), which decides
  // the order of changes.
  bool apply(const protocol::Message& change, uint64_t sender);
  // With a broker, the revision is the broker's count of the session's changes.
  void set_revision(uint32_t revision) { stored_.state.revision = revision; }

  // A conference speaker's neutral photo and landmarks (SPEC F5) replace the session's image
  // and landmark assets. Called before clients are served.
  void set_face_assets(const protocol::AssetAnnounce& photo, const protocol::AssetAnnounce& landmarks);

  // A scene's model (a mesh asset, a GLB with its textures inside) replaces the one it had (and
  // any separate texture image); every member is sent the new snapshot.
  void replace_model(const protocol::AssetAnnounce& model);

  // A turntable's tween data, encoded once, one message per cell (a member gets them after its
  // first photo), and its files as a static host serves them (the HTTP listener's /products/),
  // or why the product cannot be served (then joining is refused with that reason).
  void set_product(std::vector<protocol::TweenData> cells);
  void set_unavailable(std::string reason) { unavailable_ = std::move(reason); }
  const std::string& unavailable() const { return unavailable_; }
  const std::vector<std::shared_ptr<const protocol::Bytes>>& tween_frames() const { return tween_frames_; }
  std::shared_ptr<const ProductListing> listing() const { return unavailable_.empty() ? listing_ : nullptr; }

  // A conference session's call (its members' own faces and voices); null in other sessions.
  Call* call() { return call_.get(); }
  void start_call(CallOptions options, CallAnalyst& analyst, Call::Counters& counters, Relay& relay, const std::string& origin) {
    call_ = std::make_unique<Call>(name(), options, analyst, counters, relay, origin);
  }

  // Kept however long it goes unused (the operator's keep-scene).
  void keep() { stored_.kept = true; }

  // Set by apply(); cleared by whoever persists the state.
  bool dirty = false;

 private:
  StoredSession stored_;
  std::vector<std::weak_ptr<Connection>> members_;
  std::vector<std::shared_ptr<const protocol::Bytes>> tween_frames_;
  std::shared_ptr<const ProductListing> listing_;
  std::string unavailable_;
  std::unique_ptr<Call> call_;
};

}  // namespace inkwire::server
