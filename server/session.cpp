#include "server/session.hpp"

#include <algorithm>

#include "protocol/framing.hpp"
#include "server/connection.hpp"

namespace inkwire::server {

const protocol::AssetAnnounce* Session::find_asset(const protocol::Hash& hash) const {
  const auto& assets = stored_.state.assets;
  const auto it = std::find_if(assets.begin(), assets.end(), [&](const auto& a) { return a.hash == hash; });
  return it == assets.end() ? nullptr : &*it;
}

void Session::set_face_assets(const protocol::AssetAnnounce& photo, const protocol::AssetAnnounce& landmarks) {
  auto& assets = stored_.state.assets;
  std::erase_if(assets, [](const protocol::AssetAnnounce& a) {
    return a.kind == protocol::AssetKind::Image || a.kind == protocol::AssetKind::Landmarks;
  });
  assets.push_back(photo);
  assets.push_back(landmarks);
  ++stored_.state.revision;
  dirty = true;
}

void Session::replace_model(const protocol::AssetAnnounce& model) {
  auto& assets = stored_.state.assets;
  std::erase_if(assets, [](const protocol::AssetAnnounce& a) { return a.kind == protocol::AssetKind::Mesh || a.kind == protocol::AssetKind::Image; });
  assets.insert(assets.begin(), model);
  ++stored_.state.revision;
  dirty = true;
  // Every member draws the new model from the new snapshot: its style and camera are the session's as they were.
  const auto frame = std::make_shared<const protocol::Bytes>(protocol::encode(stored_.state));
  for (const auto& weak : members_)
    if (const auto member = weak.lock()) member->send_frame(frame, protocol::MessageType::Snapshot);
}

size_t Session::members_everywhere() const { return members_.size() + (call_ ? call_->remote_members() : 0); }

void Session::set_product(std::vector<protocol::TweenData> cells) {
  tween_frames_.clear();
  for (const protocol::TweenData& cell : cells) tween_frames_.push_back(std::make_shared<const protocol::Bytes>(protocol::encode(cell)));
  listing_ = std::make_shared<const ProductListing>(product_listing(state(), cells));
  unavailable_.clear();
}

void Session::join(const std::shared_ptr<Connection>& member) { members_.push_back(member); }

void Session::leave(const Connection* member) {
  std::erase_if(members_, [&](const std::weak_ptr<Connection>& m) {
    const auto locked = m.lock();
    return !locked || locked.get() == member;
  });
}

void Session::close_members(protocol::ErrorCode code, const std::string& reason) {
  const auto members = members_;  // closing a member leaves the session
  for (const auto& weak : members)
    if (const auto member = weak.lock()) member->close_with(code, reason);
}

bool Session::apply(const protocol::Message& change, uint64_t sender) {
  if (!protocol::apply_state_change(stored_.state, change)) return false;
  dirty = true;
  const auto frame = std::make_shared<const protocol::Bytes>(protocol::encode(change));
  for (const auto& weak : members_)
    if (const auto member = weak.lock(); member && member->id() != sender) member->send_frame(frame, protocol::type_of(change));
  return true;
}

}  // namespace inkwire::server
