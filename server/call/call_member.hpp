#pragma once
// What the parts of a call (call.cpp: roster and sending; call_intake.cpp: faces; call_voice.cpp:
// voices; call_sharing.cpp: other instances) share of a member and its limits. Private to
// server/call/.
#include <chrono>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "common/content_hash.hpp"
#include "server/call/call.hpp"

namespace inkwire::server {

using protocol::Bytes;

inline constexpr auto kSpeakingHold = std::chrono::milliseconds(400);  // silence before a speaker stops speaking
inline constexpr auto kFaceLost = std::chrono::milliseconds(1000);     // camera faces older than this: the voice moves the mouth
inline constexpr auto kStillMouth = std::chrono::milliseconds(600);    // a camera's mouth unmoved this long while the voice speaks: the voice's
inline constexpr auto kVoiceMouthStep = std::chrono::milliseconds(150); // a mouth from the voice changes at most this often
inline constexpr auto kNoFaceAfter = std::chrono::seconds(3);          // crops without a face this long: "no face found"
inline constexpr auto kVoiceMouthKeepalive = std::chrono::seconds(1);
inline constexpr auto kKeyFrameAskEvery = std::chrono::milliseconds(500);  // a key frame is asked for again after this long without one
inline constexpr auto kRejoinWithin = std::chrono::seconds(60);         // a member back this soon takes its number again
inline constexpr auto kTwinSilence = std::chrono::seconds(8);           // beyond a heartbeat and its answer: that connection is gone
inline constexpr float kLevelDecayDb = 1.5f;                           // per packet, so a level falls ~75 dB a second
// A member's face, from its camera and its voice together, at most this often: 5 member-layers a
// second (22 bytes framed) is 0.88 kbit/s, under the 1 kbit/s a face may cost (SPEC F21).
inline constexpr double kFacesPerSecond = 5;

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
inline void set_photo(protocol::CallMember& entry, std::map<protocol::Hash, Bytes>& asset_bytes, const Bytes& photo, const std::string& landmarks_json) {
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

// A member of this instance: its connection, its roster entry, its limits and what its voice and
// face said last.
struct Call::Member {
  std::weak_ptr<CallPeer> connection;
  uint64_t connection_id = 0;
  protocol::CallMember entry;  // what the roster says of it
  bool host = false;           // joined with the room's host key (an editor of the session)
  std::map<protocol::Hash, Bytes> asset_bytes;
  Bucket crops, voices;
  std::deque<Clock::time_point> drops;  // in the last second
  VoiceAnalysis voice;
  float level_db = -100;
  Clock::time_point last_voice{}, last_face{};
  std::optional<Clock::time_point> faceless_since;  // crops have come without a face since then
  bool faceless = false;                            // ... for longer than kNoFaceAfter
  std::optional<protocol::MemberLayers> camera_face;  // what the camera read last: the voice's mouth goes over it
  bool camera_mouth_sure = true;                      // ... and whether its mouth is to be trusted (CropAnalysed::mouth_sure)
  ExpressionState camera_mouth;                       // its mouth layer, and when that last moved: a mouth that
  Clock::time_point camera_mouth_moved{};             // holds still while the voice speaks is not the camera's to say
  // Whether the voice says the mouth now (SPEC F10, F21): no face read, a mouth the camera cannot
  // be sure of, or one that holds still while the member speaks (a frozen or blurred camera).
  bool voice_moves_mouth(Clock::time_point now, bool speaking) const {
    return !entry.camera || faceless || now - last_face > kFaceLost || !camera_mouth_sure || (speaking && now - camera_mouth_moved > kStillMouth);
  }
  ExpressionState voice_mouth;
  Clock::time_point voice_mouth_sent{};
  Bucket faces;                                      // its camera's and its voice's faces, one budget
  std::optional<protocol::MemberLayers> face_waiting;  // the newest face that found no room yet
  uint32_t latest_voice_time = 0;
  Clock::time_point key_frame_asked{};
};

}  // namespace inkwire::server
