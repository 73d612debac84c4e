#pragma once
// Keeps a SessionView in step with a SessionClient: takes each newer state, downloads assets it
// lists that are not cached yet (once; afterwards only control messages flow), and updates the
// view. Call poll() once per frame on the render thread.
#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"

namespace inkwire {

class SessionSync {
 public:
  SessionSync(SessionClient& client, AssetCache& cache) : client_(client), cache_(cache) {}

  // True when the view changed. Throws inkwire::Error if an asset cannot be fetched.
  bool poll();
  SessionView& view() { return view_; }
  const protocol::Snapshot& state() const { return state_; }

 private:
  SessionClient& client_;
  AssetCache& cache_;
  SessionView view_;
  protocol::Snapshot state_;
  std::vector<protocol::AssetAnnounce> fetched_;
  std::vector<std::filesystem::path> files_;
  uint64_t seen_ = ~uint64_t(0);
};

}  // namespace inkwire
