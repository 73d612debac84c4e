#include "client/viewer/session_sync.hpp"

#include "common/error.hpp"

namespace inkwire {
namespace {

bool has_product(const protocol::Snapshot& state) { return !state.product.directions.empty(); }

// The k-th asset of `kind` (a product's photos and mattes are listed in sample order).
const protocol::AssetAnnounce* nth_asset(const protocol::Snapshot& state, protocol::AssetKind kind, int k) {
  for (const protocol::AssetAnnounce& a : state.assets)
    if (a.kind == kind && k-- == 0) return &a;
  return nullptr;
}

}  // namespace

bool SessionSync::poll() {
  bool changed = false;
  const uint64_t updates = client_.updates();
  if (updates != seen_) {
    seen_ = updates;
    state_ = client_.state();
    // A product's photos are fetched one per poll below, nearest the view first, so the first
    // view shows after one photo; other sessions' assets all at once.
    if (!has_product(state_) && state_.assets != fetched_) {
      files_ = client_.fetch_assets(state_, cache_);
      fetched_ = state_.assets;
    }
    view_.update(state_, files_);
    if (TurntableView* t = view_.turntable()) t->add_cells(client_.tween_cells());
    changed = true;
  }
  if (TurntableView* t = view_.turntable()) {
    const int next = t->next_sample(view_.orbit());
    if (next >= 0) {
      const protocol::AssetAnnounce* photo = nth_asset(state_, protocol::AssetKind::Samples, next);
      const protocol::AssetAnnounce* matte = nth_asset(state_, protocol::AssetKind::Matte, next);
      if (!photo) throw Error("the product lists no photo for sample " + std::to_string(next));
      // The small matte first: the server sends the tween data once the first photo is out.
      const std::filesystem::path matte_file = matte ? client_.fetch_asset(*matte, cache_) : std::filesystem::path();
      t->add_sample(next, client_.fetch_asset(*photo, cache_), matte_file);
      changed = true;
    }
  }
  return changed;
}

}  // namespace inkwire
