#include "server/call/call.hpp"

#include <algorithm>
#include <deque>
#include <tuple>

#include "common/content_hash.hpp"
#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "server/connection.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {
namespace {

using protocol::Bytes;
constexpr auto kSpeakingHold = std::chrono::milliseconds(400);  // silence before a speaker stops speaking
constexpr auto kFaceLost = std::chrono::milliseconds(1000);     // camera faces older than this: the voice moves the mouth
constexpr auto kVoiceMouthStep = std::chrono::milliseconds(150); // a mouth from the voice changes at most this often
constexpr auto kNoFaceAfter = std::chrono::seconds(3);          // crops without a face this long: "no face found"
constexpr auto kVoiceMouthKeepalive = std::chrono::seconds(1);
constexpr auto kKeyFrameAskEvery = std::chrono::milliseconds(500);  // a key frame is asked for again after this long without one
constexpr auto kRejoinWithin = std::chrono::seconds(60);         // a member back this soon takes its number again
constexpr auto kTwinSilence = std::chrono::seconds(8);           // beyond a heartbeat and its answer: that connection is gone
constexpr float kLevelDecayDb = 1.5f;                           // per packet, so a level falls ~75 dB a second

// A token bucket: `rate` a second, a second's worth at once.
struct Bucket {
  double tokens = 0;
  Call::Clock::time_point last{};
  bool take(double rate, Call::Clock::time_point now) {
    tokens = std::min(rate, tokens + rate * std::chrono::duration<double>(now - last).count());
    last = now;
    if (tokens < 1) return false;
    tokens -= 1;
    return true;
  }
};

// A member's neutral photo and landmarks become its assets: listed in its roster entry by hash,
// their bytes kept beside it to be served.
void set_photo(protocol::CallMember& entry, std::map<protocol::Hash, Bytes>& asset_bytes, const Bytes& photo, const std::string& landmarks_json) {
  asset_bytes.clear();
  entry.assets.clear();
  const std::string stem = "member-" + std::to_string(entry.member);
  const Bytes landmarks(landmarks_json.begin(), landmarks_json.end());
  for (const auto& [bytes, kind, name] : {std::tuple{&photo, protocol::AssetKind::Image, stem + ".jpg"},
                                          std::tuple{&landmarks, protocol::AssetKind::Landmarks, stem + ".landmarks.json"}}) {
    const protocol::Hash hash = content_hash(bytes->data(), bytes->size());
    entry.assets.push_back({.hash = hash, .size = bytes->size(), .kind = kind, .name = name});
    asset_bytes[hash] = *bytes;
  }
}

}  // namespace

struct Call::Member {
  std::weak_ptr<Connection> connection;
  uint64_t connection_id = 0;
  protocol::CallMember entry;  // what the roster says of it
  std::map<protocol::Hash, Bytes> asset_bytes;
  Bucket crops, voices;
  std::deque<Clock::time_point> drops;  // in the last second
  VoiceAnalysis voice;
  float level_db = -100;
  Clock::time_point last_voice{}, last_face{};
  std::optional<Clock::time_point> faceless_since;  // crops have come without a face since then
  bool faceless = false;                            // ... for longer than kNoFaceAfter
  ExpressionState voice_mouth;
  Clock::time_point voice_mouth_sent{};
  uint32_t latest_voice_time = 0;
  Clock::time_point key_frame_asked{};
};

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

void Call::join(const std::shared_ptr<Connection>& connection, const std::string& name) {
  leave(connection->id());
  auto m = std::make_unique<Member>();
  m->connection = connection;
  m->connection_id = connection->id();
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

bool Call::dropped(Member& m, const std::string& reason) {
  ++counters_.drops[reason];
  const auto now = Clock::now();
  m.drops.push_back(now);
  while (!m.drops.empty() && now - m.drops.front() > std::chrono::seconds(1)) m.drops.pop_front();
  // Sustained at twice the allowed rates on top of what was allowed: flooding.
  if (double(m.drops.size()) <= 2 * (options_.crops_per_second + options_.voice_per_second)) return false;
  log_warn("call-flood", {{"session", session_}, {"member", m.entry.member}, {"reason", reason}});
  if (const auto c = m.connection.lock())
    c->close_with(protocol::ErrorCode::Refused, "flooding the call: over " + std::to_string(m.drops.size()) + " dropped messages a second (" + reason + ")");
  return true;
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

bool Call::admitted(Member& m, bool voice, size_t size) {
  const char* what = voice ? "voice" : "crop";
  if (!(voice ? m.voices : m.crops).take(voice ? options_.voice_per_second : options_.crops_per_second, Clock::now())) {
    dropped(m, std::string(what) + "-too-frequent");
    return false;
  }
  if (size > (voice ? options_.max_voice_bytes : options_.max_crop_bytes)) {
    dropped(m, std::string(what) + "-too-large");
    return false;
  }
  return true;
}

void Call::crop(uint64_t connection, protocol::FaceCrop crop) {
  Member* m = find(connection);
  if (!m || !admitted(*m, false, crop.jpeg.size())) return;
  if (!looks_like_jpeg(crop.jpeg)) {
    dropped(*m, "crop-not-jpeg");
    return;
  }
  analyst_.crop({session_, m->entry.member}, std::move(crop));
}

// Checked here for rate and size only: the bitstream is read on the analyst's thread, where a
// frame that fails is counted and the stream waits for the key frame asked for in analysed().
void Call::video(uint64_t connection, protocol::FaceVideo frame) {
  Member* m = find(connection);
  if (!m || !admitted(*m, false, frame.vp8.size())) return;  // the gap it leaves asks for a key frame
  if (analyst_.video({session_, m->entry.member}, std::move(frame))) return;
  ++counters_.drops["video-analysis-behind"];  // the server's doing, not the member's: no flood is counted
  ask_for_key_frame(*m);
}

void Call::ask_for_key_frame(Member& m) {
  const auto now = Clock::now();
  if (now - m.key_frame_asked < kKeyFrameAskEvery) return;
  m.key_frame_asked = now;
  if (const auto c = m.connection.lock()) c->send(protocol::KeyFrameRequest{});
}

void Call::voice(uint64_t connection, protocol::VoiceFrame frame) {
  Member* m = find(connection);
  if (!m || !admitted(*m, true, frame.opus.size())) return;
  const auto now = Clock::now();
  const auto reading = m->voice.read(frame.opus);
  if (!reading) {
    dropped(*m, "voice-not-opus");
    return;
  }
  m->level_db = std::max(reading->level_db, m->level_db - kLevelDecayDb);
  if (reading->level_db > VoiceAnalysis::kSilenceDb) m->last_voice = now;
  m->latest_voice_time = frame.time_ms;
  update_speakers(now);
  // The sender's own number on what is relayed: a member speaks only as itself.
  frame.member = m->entry.member;
  if (m->entry.speaking) {
    counters_.voice_relayed += send_to_others(*m, frame);
    relay_.share_call({.origin = origin_, .session = session_, .message = frame});
  }
  // Without a face to read, the voice moves the mouth (SPEC F10).
  const bool face_gone = !m->entry.camera || m->faceless || now - m->last_face > kFaceLost;
  // Mouths change with syllables, four to seven a second: one every packet would be more codes
  // than speech needs (SPEC F14 counts them).
  const bool changed = !(reading->mouth == m->voice_mouth) && now - m->voice_mouth_sent >= kVoiceMouthStep;
  if (face_gone && (changed || now - m->voice_mouth_sent > kVoiceMouthKeepalive)) {
    m->voice_mouth = reading->mouth;
    m->voice_mouth_sent = now;
    const protocol::MemberFace face{.member = m->entry.member, .time_ms = frame.time_ms,
                                    .expression = {.code = uint8_t(reading->mouth.expression), .intensity = reading->mouth.intensity},
                                    .source = protocol::FaceSource::Voice};
    send_to_all(face);
    relay_.share_call({.origin = origin_, .session = session_, .message = face});
  }
}

void Call::update_speakers(Clock::time_point now) {
  // The K loudest of those who spoke lately, on this instance and the others alike (each
  // instance shares its own loudest: the call's loudest are among them); the roster says who.
  struct Talker {
    float level_db;
    protocol::CallMember* entry;
  };
  std::vector<Talker> talking, everyone;
  for (auto& [id, m] : members_) {
    everyone.push_back({m->level_db, &m->entry});
    if (m->entry.microphone && now - m->last_voice < kSpeakingHold) talking.push_back(everyone.back());
  }
  for (auto& [key, r] : remotes_) {
    everyone.push_back({r.level_db, &r.entry});
    if (r.entry.microphone && now - r.last_voice < kSpeakingHold) talking.push_back(everyone.back());
  }
  std::sort(talking.begin(), talking.end(), [](const Talker& a, const Talker& b) { return a.level_db > b.level_db; });
  if (talking.size() > size_t(options_.loudest)) talking.resize(size_t(options_.loudest));
  bool changed = false;
  for (const Talker& t : everyone) {
    const bool speaking = std::any_of(talking.begin(), talking.end(), [&](const Talker& k) { return k.entry == t.entry; });
    changed |= speaking != t.entry->speaking;
    t.entry->speaking = speaking;
  }
  if (changed) send_roster();
}

void Call::analysed(const PhotoAnalysed& result) {
  Member* m = find_member(result.who.member);
  if (!m) return;
  const auto c = m->connection.lock();
  if (!result.error.empty()) {
    if (c) c->send(protocol::ErrorMessage{.code = protocol::ErrorCode::NotAllowed, .reason = result.error});
    return;
  }
  set_photo(m->entry, m->asset_bytes, result.photo, result.landmarks);
  relay_.share_call({.origin = origin_, .session = session_, .photo_member = m->entry.member, .photo = result.photo, .landmarks = result.landmarks});
  send_roster();
}

void Call::analysed(const CropAnalysed& result) {
  Member* m = find_member(result.who.member);
  if (!m) return;
  const auto now = Clock::now();
  const auto connection = m->connection.lock();
  if (result.frames_dropped > 0) {
    log_info("call-video-dropped", {{"session", session_}, {"member", m->entry.member}, {"frames", result.frames_dropped}, {"reason", result.error}});
    for (int k = 0; k < result.frames_dropped; ++k)
      if (dropped(*m, "video-unreadable")) return;
  }
  if (result.key_frame_wanted) ask_for_key_frame(*m);
  if (!result.region) {
    if (!result.error.empty() && result.frames_dropped == 0) dropped(*m, "crop-unreadable");
    return;
  }
  ++counters_.crops;
  counters_.seconds += result.analysis_ms / 1000.0;
  if (connection) connection->send(*result.region);
  if (result.region->found) {
    m->last_face = now;
    m->faceless_since.reset();
  } else if (!m->faceless_since) {
    m->faceless_since = now;
  }
  m->faceless = m->faceless_since && now - *m->faceless_since > kNoFaceAfter;
  if (m->entry.face_found == m->faceless) {
    m->entry.face_found = !m->faceless;
    send_roster();
  }
  // Everyone, the member too: its own tile shows what the others see of it.
  if (result.face) {
    send_to_all(*result.face);
    relay_.share_call({.origin = origin_, .session = session_, .message = *result.face});
  }
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

void Call::share_roster() {
  roster_shared_ = Clock::now();
  protocol::Roster own;
  for (const auto& [id, m] : members_) own.members.push_back(m->entry);
  if (own.members.size() > protocol::kMaxMembers) own.members.resize(protocol::kMaxMembers);
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
    for (const protocol::CallMember& m : roster->members) {
      Remote* r = remote_member(share.origin, m.member, true);
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
  const auto frame = std::make_shared<const Bytes>(protocol::encode(message));
  for (const auto& [id, m] : members_)
    if (const auto c = m->connection.lock()) {
      c->send_frame(frame, protocol::type_of(message));
      if (protocol::type_of(message) == protocol::MessageType::VoiceFrame) ++counters_.voice_relayed;
    }
}

void Call::send_roster() {
  protocol::Roster roster;
  for (const auto& [id, m] : members_) roster.members.push_back(m->entry);
  for (const auto& [key, r] : remotes_) roster.members.push_back(r.entry);
  if (roster.members.size() > protocol::kMaxMembers) roster.members.resize(protocol::kMaxMembers);
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

size_t Call::send_to_others(const Member& from, const protocol::Message& message) {
  const auto frame = std::make_shared<const Bytes>(protocol::encode(message));
  size_t sent = 0;
  for (const auto& [id, m] : members_)
    if (m.get() != &from)
      if (const auto c = m->connection.lock()) c->send_frame(frame, protocol::type_of(message)), ++sent;
  return sent;
}

}  // namespace inkwire::server
