#include "server/call/call.hpp"

// A call's roster and sending (SPEC F8, F19): members joining under a number (their own again
// when they come back), leaving, publishing, their photos, and the messages that go to them.
// Faces: call_intake.cpp; voices: call_voice.cpp; other instances: call_sharing.cpp.
#include <algorithm>

#include "common/log.hpp"
#include "protocol/face_versions.hpp"
#include "protocol/framing.hpp"
#include "protocol/versions.hpp"
#include "server/call/call_member.hpp"
#include "server/call/call_peer.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {

Call::Call(std::string session, CallOptions options, CallAnalyst& analyst, Counters& counters, Relay& relay, std::string origin)
    : session_(std::move(session)), options_(options), analyst_(analyst), counters_(counters), relay_(relay), origin_(std::move(origin)) {}

Call::~Call() {
  for (const auto& [id, m] : members_) analyst_.forget({session_, m->entry.member});
}

Call::Member* Call::find(uint64_t connection) {
  const auto it = members_.find(connection);
  return it == members_.end() ? nullptr : it->second.get();
}

Call::Member* Call::find_member(uint16_t number) {
  for (auto& [id, m] : members_)
    if (m->entry.member == number) return m.get();
  return nullptr;
}

uint16_t Call::take_number() {
  // Numbers are not reused while the number space lasts, so a late message from one who left
  // never lands on a newcomer.
  const auto taken = [&](uint16_t n) {
    return find_member(n) || std::any_of(remotes_.begin(), remotes_.end(), [&](const auto& r) { return r.second.entry.member == n; });
  };
  while (next_number_ == 0 || taken(next_number_)) ++next_number_;
  return next_number_++;
}

uint16_t Call::number_for(const std::string& name, const std::string& address) {
  const auto now = Clock::now();
  std::erase_if(departed_, [&](const auto& d) { return now - d.second.when > kRejoinWithin; });
  for (auto it = members_.begin(); it != members_.end(); ++it) {
    const auto twin = it->second->connection.lock();
    if (it->second->entry.name != name || !twin || twin->address() != address || twin->silent_for() < kTwinSilence) continue;
    log_info("call-rejoin-replaces", {{"session", session_}, {"member", it->second->entry.member}, {"name", name}});
    const uint16_t number = it->second->entry.member;
    analyst_.forget({session_, number});
    members_.erase(it);
    twin->close_with(protocol::ErrorCode::Refused, "this member joined again on another connection");
    return number;
  }
  if (const auto it = departed_.find({name, address}); it != departed_.end()) {
    const uint16_t number = it->second.member;
    departed_.erase(it);
    const bool taken = find_member(number) || std::any_of(remotes_.begin(), remotes_.end(), [&](const auto& r) { return r.second.entry.member == number; });
    if (!taken) return number;
  }
  return take_number();
}

void Call::join(const std::shared_ptr<CallPeer>& connection, const std::string& name, bool host) {
  leave(connection->id());
  auto m = std::make_unique<Member>();
  m->connection = connection;
  m->connection_id = connection->id();
  m->host = host;
  m->entry.member = name.empty() ? take_number() : number_for(name, connection->address());
  m->entry.name = name.empty() ? "member " + std::to_string(m->entry.member) : name;
  members_[connection->id()] = std::move(m);
  send_roster();
  share_roster();
}

void Call::leave(uint64_t connection) {
  const auto it = members_.find(connection);
  if (it == members_.end()) return;
  analyst_.forget({session_, it->second->entry.member});
  if (const auto c = it->second->connection.lock())
    departed_[{it->second->entry.name, c->address()}] = {.member = it->second->entry.member, .when = Clock::now()};
  members_.erase(it);
  send_roster();
  share_roster();
}

void Call::set_locked(bool locked) {
  if (locked_ == locked) return;
  locked_ = locked;
  log_info(locked ? "room-locked" : "room-unlocked", {{"session", session_}});
  send_roster();
  share_roster();  // the other instances take newcomers no more either
}

bool Call::remove(uint16_t member, const std::string& reason) {
  Member* m = find_member(member);
  if (!m) {
    // A member of another instance: that instance removes it (and its roster then says so).
    const auto remote = std::find_if(remotes_.begin(), remotes_.end(), [&](const auto& r) { return r.second.entry.member == member; });
    if (remote == remotes_.end()) return false;
    log_info("room-member-removed", {{"session", session_}, {"member", member}, {"name", remote->second.entry.name}, {"on", remote->first.first}});
    relay_.share_call({.origin = origin_, .session = session_, .removal = CallShare::Removal{remote->first.first, remote->first.second, reason}});
    remotes_.erase(remote);
    send_roster();
    return true;
  }
  log_info("room-member-removed", {{"session", session_}, {"member", member}, {"name", m->entry.name}});
  const auto connection = m->connection.lock();
  // Not kept among those who left: coming back, it is a newcomer (refused while the room is locked).
  analyst_.forget({session_, member});
  members_.erase(m->connection_id);
  send_roster();
  share_roster();
  if (connection) connection->close_with(protocol::ErrorCode::Removed, reason);
  return true;
}

std::string Call::host_name() const {
  for (const auto& [id, m] : members_)
    if (m->host) return m->entry.name;
  for (const auto& [key, r] : remotes_)
    if (r.host) return r.entry.name;
  return "";
}

void Call::publish(uint64_t connection, const protocol::Publish& publish) {
  Member* m = find(connection);
  if (!m) return;
  if (m->entry.camera == publish.camera && m->entry.microphone == publish.microphone) return;
  m->entry.camera = publish.camera;
  m->entry.microphone = publish.microphone;
  if (!publish.camera) m->faceless_since.reset(), m->faceless = false, m->entry.face_found = true;
  send_roster();
  share_roster();
}

void Call::photo(uint64_t connection, Bytes jpeg) {
  if (Member* m = find(connection)) analyst_.photo({session_, m->entry.member}, std::move(jpeg));
}

const Bytes* Call::asset(const protocol::Hash& hash) const {
  for (const auto& [id, m] : members_)
    if (const auto it = m->asset_bytes.find(hash); it != m->asset_bytes.end()) return &it->second;
  for (const auto& [key, r] : remotes_)
    if (const auto it = r.asset_bytes.find(hash); it != r.asset_bytes.end()) return &it->second;
  return nullptr;
}

void Call::tick() {
  const auto now = Clock::now();
  update_speakers(now);
  if (now - roster_shared_ > std::chrono::seconds(2)) share_roster();
  const size_t before = remotes_.size();
  std::erase_if(remotes_, [&](const auto& r) { return now - r.second.heard > std::chrono::seconds(6); });
  if (remotes_.size() != before) send_roster();
}

void Call::send_roster() {
  protocol::Roster roster;
  for (const auto& [id, m] : members_) roster.members.push_back(m->entry);
  for (const auto& [key, r] : remotes_) roster.members.push_back(r.entry);
  if (roster.members.size() > protocol::kMaxMembers) roster.members.resize(protocol::kMaxMembers);
  roster.locked = locked_;
  for (const auto& [id, m] : members_)
    if (m->host) roster.host = m->entry.member;
  for (const auto& [key, r] : remotes_)
    if (r.host && roster.host == 0) roster.host = r.entry.member;
  for (const auto& [id, m] : members_)
    if (const auto c = m->connection.lock()) {
      roster.you = m->entry.member;
      c->send(roster);
    }
}

void Call::send_to_all(const protocol::Message& message) {
  const auto frame = std::make_shared<const Bytes>(protocol::encode(message));
  for (const auto& [id, m] : members_)
    if (const auto c = m->connection.lock()) c->send_frame(frame, protocol::type_of(message));
}

void Call::send_face(const protocol::MemberLayers& face) {
  const auto layers = std::make_shared<const Bytes>(protocol::encode(face));
  std::shared_ptr<const Bytes> legacy;  // encoded once, if any peer needs it
  for (const auto& [id, m] : members_)
    if (const auto c = m->connection.lock()) {
      if (c->version() >= protocol::kLayersVersion) {
        c->send_frame(layers, protocol::MessageType::MemberLayers);
        continue;
      }
      if (!legacy) legacy = std::make_shared<const Bytes>(protocol::encode(protocol::member_face_of(face)));
      c->send_frame(legacy, protocol::MessageType::MemberFace);
    }
}

void Call::offer_face(Member& m, const protocol::MemberLayers& face, Clock::time_point now) {
  m.face_waiting = face;
  send_waiting_face(m, now);
}

void Call::send_waiting_face(Member& m, Clock::time_point now) {
  if (!m.face_waiting || !m.faces.take(kFacesPerSecond, now)) return;
  send_face(*m.face_waiting);
  relay_.share_call({.origin = origin_, .session = session_, .message = *m.face_waiting});
  m.face_waiting.reset();
}

size_t Call::send_to_others(const Member& from, const protocol::Message& message) {
  const auto frame = std::make_shared<const Bytes>(protocol::encode(message));
  size_t sent = 0;
  for (const auto& [id, m] : members_)
    if (m.get() != &from)
      if (const auto c = m->connection.lock()) c->send_frame(frame, protocol::type_of(message)), ++sent;
  return sent;
}

}  // namespace inkwire::server
