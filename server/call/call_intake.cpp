#include "server/call/call.hpp"

// A call's intake of faces (SPEC F9, F17): crops and video within each member's rate and size,
// read on the analyst's thread, their results shown to everyone; what is dropped, counted, and a
// member that floods closed.

#include <algorithm>

#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "server/call/call_member.hpp"
#include "server/call/call_peer.hpp"
#include "server/relay/relay.hpp"

namespace inkwire::server {

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
  if (!m) return;
  const MemberKey who{session_, m->entry.member};
  if (!admitted(*m, false, frame.vp8.size())) {
    // Counted once, as refused; the frames after it wait for a key frame instead of each
    // failing to decode (and being counted again as unreadable).
    analyst_.video_lost(who);
    ask_for_key_frame(*m);
    return;
  }
  if (analyst_.video(who, std::move(frame))) return;
  // The stream waits for a key frame after a gap (the analyst fell behind, or a frame was refused
  // above and counted there): no flood is counted for it.
  ++counters_.drops["video-awaiting-key-frame"];
  ask_for_key_frame(*m);
}

void Call::ask_for_key_frame(Member& m) {
  const auto now = Clock::now();
  if (now - m.key_frame_asked < kKeyFrameAskEvery) return;
  m.key_frame_asked = now;
  if (const auto c = m.connection.lock()) c->send(protocol::KeyFrameRequest{});
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
  if (result.region->found) m->camera_mouth_sure = result.mouth_sure;
  if (result.face) {
    m->camera_face = *result.face;
    if (!(result.face->mouth == m->camera_mouth)) m->camera_mouth = result.face->mouth, m->camera_mouth_moved = now;
    protocol::MemberLayers face = *result.face;
    // A mouth the camera cannot say: the voice's, while the member speaks (SPEC F21).
    const bool speaking = now - m->last_voice < kSpeakingHold;
    if (speaking && m->voice_moves_mouth(now, speaking)) face.mouth = m->voice_mouth;
    offer_face(*m, face, now);
  } else {
    send_waiting_face(*m, now);
  }
}

}  // namespace inkwire::server
