#include "server/call/call.hpp"

// A call across instances (SPEC F19): this instance's roster shared through the broker, and what
// other instances' members publish taken in under numbers of this instance.

#include <algorithm>

#include "common/log.hpp"
#include "protocol/face_versions.hpp"
#include "protocol/framing.hpp"
#include "server/call/call_member.hpp"
#include "server/call/call_peer.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {

void Call::share_roster() {
  roster_shared_ = Clock::now();
  protocol::Roster own;
  for (const auto& [id, m] : members_) {
    own.members.push_back(m->entry);
    if (m->host) own.host = m->entry.member;
  }
  if (own.members.size() > protocol::kMaxMembers) own.members.resize(protocol::kMaxMembers);
  own.locked = locked_;  // the room's, when its host is here (own.host); others read it only then
  relay_.share_call({.origin = origin_, .session = session_, .message = own});
}

Call::Remote* Call::remote_member(const std::string& origin, uint16_t number, bool create) {
  const auto key = std::pair(origin, number);
  if (const auto it = remotes_.find(key); it != remotes_.end()) return &it->second;
  if (!create) return nullptr;
  Remote& r = remotes_[key];
  r.entry.member = take_number();
  r.heard = Clock::now();
  return &r;
}

void Call::remote(const CallShare& share) {
  const auto now = Clock::now();
  if (share.removal) {
    // The host, on another instance, removed a member of this one.
    if (share.removal->instance != origin_) return;
    if (const Member* m = find_member(share.removal->member)) remove(m->entry.member, share.removal->reason);
    return;
  }
  if (share.photo_member) {
    Remote* r = remote_member(share.origin, share.photo_member, true);
    set_photo(r->entry, r->asset_bytes, share.photo, share.landmarks);
    send_roster();
    return;
  }
  if (!share.message) return;
  if (const auto* roster = std::get_if<protocol::Roster>(&*share.message)) {
    // The origin's members as they are now: new ones join, gone ones leave.
    std::erase_if(remotes_, [&](const auto& r) {
      return r.first.first == share.origin &&
             std::none_of(roster->members.begin(), roster->members.end(), [&](const auto& m) { return m.member == r.first.second; });
    });
    // The instance the host is on says whether the room is locked.
    if (roster->host != 0 && roster->locked != locked_) {
      locked_ = roster->locked;
      log_info(locked_ ? "room-locked" : "room-unlocked", {{"session", session_}, {"by", share.origin}});
    }
    for (const protocol::CallMember& m : roster->members) {
      Remote* r = remote_member(share.origin, m.member, true);
      r->host = roster->host == m.member;
      const uint16_t local = r->entry.member;
      const bool speaking = r->entry.speaking;  // among the call's loudest: this instance's reading
      std::vector<protocol::AssetAnnounce> assets = std::move(r->entry.assets);  // its photo comes on its own
      r->entry = m;
      r->entry.member = local;
      r->entry.speaking = speaking;
      r->entry.assets = std::move(assets);
      r->heard = now;
    }
    send_roster();
    return;
  }
  protocol::Message message = *share.message;
  uint16_t* member = std::visit([](auto& m) -> uint16_t* {
    if constexpr (requires { m.member; }) return &m.member;
    return nullptr;
  }, message);
  Remote* r = member ? remote_member(share.origin, *member, false) : nullptr;
  if (!r) return;  // not in a roster heard yet: its next roster brings it
  *member = r->entry.member;
  r->heard = now;
  if (const auto* voice = std::get_if<protocol::VoiceFrame>(&message)) {
    // Its origin shared it as one of its own loudest; here it plays only if among the call's.
    const auto reading = r->voice.read(voice->opus);
    if (!reading) return;
    r->level_db = std::max(reading->level_db, r->level_db - kLevelDecayDb);
    if (reading->level_db > VoiceAnalysis::kSilenceDb) r->last_voice = now;
    update_speakers(now);
    if (!r->entry.speaking) return;
  }
  // From an instance of before layers: its one code as layers.
  if (const auto* face = std::get_if<protocol::MemberFace>(&message)) message = protocol::member_layers_of(*face);
  if (const auto* face = std::get_if<protocol::MemberLayers>(&message)) {
    send_face(*face);
    return;
  }
  const auto frame = std::make_shared<const Bytes>(protocol::encode(message));
  for (const auto& [id, m] : members_)
    if (const auto c = m->connection.lock()) {
      c->send_frame(frame, protocol::type_of(message));
      if (protocol::type_of(message) == protocol::MessageType::VoiceFrame) ++counters_.voice_relayed;
    }
}

}  // namespace inkwire::server
