#include "client/viewer/session_sync.hpp"

namespace inkwire {

bool SessionSync::poll() {
  const uint64_t updates = client_.updates();
  if (updates == seen_) return false;
  seen_ = updates;
  state_ = client_.state();
  if (state_.assets != fetched_) {
    files_ = client_.fetch_assets(state_, cache_);
    fetched_ = state_.assets;
  }
  view_.update(state_, files_);
  return true;
}

}  // namespace inkwire
