#include "server/call/call.hpp"

// A call's voices (SPEC F10, F19): each packet read for its level and mouth, relayed while its
// member is among the call's loudest few, and the mouth moved by the voice when no face is read.

#include <algorithm>

#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "server/call/call_member.hpp"
#include "server/call/call_peer.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {

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
  // Without a face to read, or a mouth the camera cannot say, the voice moves the mouth (SPEC F10, F21).
  // (Speaking: heard lately, so the pauses between syllables close the mouth too.)
  const bool face_gone = m->voice_moves_mouth(now, now - m->last_voice < kSpeakingHold);
  // Mouths change with syllables, four to seven a second: one every packet would be more codes
  // than speech needs (SPEC F14 counts them).
  const bool changed = !(reading->mouth == m->voice_mouth) && now - m->voice_mouth_sent >= kVoiceMouthStep;
  if (face_gone && (changed || now - m->voice_mouth_sent > kVoiceMouthKeepalive)) {
    m->voice_mouth = reading->mouth;
    m->voice_mouth_sent = now;
    // The mouth over what the camera read last (its expression, eyes and pose), while the camera is
    // on: a member whose face the camera lost a moment keeps its smile; with the camera off, a
    // neutral face.
    protocol::MemberLayers face = m->entry.camera && m->camera_face ? *m->camera_face : protocol::MemberLayers{};
    face.member = m->entry.member;
    face.time_ms = frame.time_ms;
    face.mouth = reading->mouth;
    face.source = protocol::FaceSource::Voice;
    offer_face(*m, face, now);
  } else {
    send_waiting_face(*m, now);
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

}  // namespace inkwire::server
