#include "client/viewer/session_sync.hpp"

#include <algorithm>
#include <optional>

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

SessionSync::~SessionSync() {
  if (photo_.valid()) photo_.wait();
}

bool SessionSync::poll() {
  bool changed = false;
  const uint64_t updates = client_.updates();
  if (updates != seen_) {
    seen_ = updates;
    state_ = client_.state();
    // A product's photos are fetched one at a time below, nearest the view first, so the first
    // view shows after one photo; other sessions' assets all at once.
    if (!has_product(state_) && state_.assets != fetched_) {
      if (photo_.valid()) photo_.wait();  // one thread writes the cache at a time
      files_ = client_.fetch_assets(state_, cache_);
      fetched_ = state_.assets;
    }
    view_.update(state_, files_);
    if (TurntableView* t = view_.turntable()) t->add_cells(client_.tween_cells());
    changed = true;
  }
  if (state_.kind == protocol::SessionKind::Conference) changed |= poll_call();
  if (TurntableView* t = view_.turntable()) {
    changed |= take_photo(*t);
    if (!photo_.valid())
      if (const auto next = t->next_fetch(view_.orbit())) fetch_photo(*next);
  }
  return changed;
}

bool SessionSync::poll_call() {
  bool changed = false;
  const protocol::Roster roster = client_.roster();
  if (!(roster == roster_)) {
    roster_ = roster;
    for (const protocol::CallMember& m : roster_.members) {
      if (m.assets.size() != 2) continue;
      std::vector<std::filesystem::path> files;
      for (const protocol::AssetAnnounce& a : m.assets) files.push_back(client_.fetch_asset(a, cache_));  // small, once
      member_files_[m.member] = files;
    }
    view_.update_call(roster_, member_files_);
    changed = true;
  }
  for (const auto& voice : client_.take_voice()) audio_.add(voice.frame, voice.arrived);
  for (protocol::MemberLayers& face : client_.take_member_faces()) faces_waiting_.push_back(face);
  // A face comes when the sound of its moment plays (its member's clock mapped as the voice's),
  // so the mouth moves with the voice; a member never heard is shown at once.
  const auto now = std::chrono::steady_clock::now();
  for (auto it = faces_waiting_.begin(); it != faces_waiting_.end();) {
    const auto due = audio_.local_time(it->member, it->time_ms);
    if (due && *due > now) {
      ++it;
      continue;
    }
    view_.set_member_face(*it);
    it = faces_waiting_.erase(it);
    changed = true;
  }
  return changed;
}

void SessionSync::fetch_photo(TurntableView::PhotoFetch which) {
  // A finer level's photos follow the first level's, level after level (protocol/SPEC.md).
  const int samples = int(state_.product.directions.size());
  const protocol::AssetAnnounce* photo = which.level == 0 ? nth_asset(state_, protocol::AssetKind::Samples, which.sample)
                                                          : nth_asset(state_, protocol::AssetKind::Zoom, (which.level - 1) * samples + which.sample);
  const protocol::AssetAnnounce* matte = nth_asset(state_, protocol::AssetKind::Matte, which.sample);
  if (!photo)
    throw Error("the product lists no photo for sample " + std::to_string(which.sample) + (which.level ? " at zoom level " + std::to_string(which.level) : ""));
  photo_ = std::async(std::launch::async, [this, which, photo = *photo, matte = matte ? std::optional(*matte) : std::nullopt] {
    // The small matte first: the server sends the tween data once the first photo is out.
    const std::filesystem::path matte_file = matte ? client_.fetch_asset(*matte, cache_) : std::filesystem::path();
    return FetchedPhoto{which, photo, TurntableView::sample_image(client_.fetch_asset(photo, cache_), matte_file)};
  });
}

bool SessionSync::take_photo(TurntableView& product) {
  if (!photo_.valid() || photo_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
  const FetchedPhoto fetched = photo_.get();
  // The session may have moved on to another product while the photo came.
  if (std::find(state_.assets.begin(), state_.assets.end(), fetched.photo) == state_.assets.end()) return false;
  product.add_sample(fetched.which.sample, fetched.image, fetched.which.level);
  return true;
}

}  // namespace inkwire
