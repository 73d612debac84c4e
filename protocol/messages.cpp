// One serialise function per message: reads (with validation), writes and measures.
#include "protocol/messages.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <utility>

#include <glm/geometric.hpp>

#include "protocol/framing.hpp"

namespace inkwire::protocol {
namespace {

void check(bool ok, const char* reason) {
  if (!ok) throw ProtocolError(reason);
}

template <class Stream, class Enum>
void enumeration(Stream& s, Enum& v, unsigned first, unsigned last, const char* what) {
  if constexpr (sizeof(Enum) == 1) {
    uint8_t raw = uint8_t(v);
    s.u8(raw);
    v = Enum(raw);
  } else {
    uint16_t raw = uint16_t(v);
    s.u16(raw);
    v = Enum(raw);
  }
  if constexpr (Stream::reading)
    if (unsigned(v) < first || unsigned(v) > last) throw ProtocolError(std::string("unknown ") + what + " " + std::to_string(unsigned(v)));
}

template <class Stream>
void flag(Stream& s, bool& v, const char* what) {
  uint8_t raw = v;
  s.u8(raw);
  if constexpr (Stream::reading) {
    if (raw > 1) throw ProtocolError(std::string(what) + " is not 0 or 1");
    v = raw == 1;
  }
}

// Names (sessions, renderers, setting keys) are plain: letters, digits and - _ . + =, so they
// can be logged, used as keys and passed to the style registry without quoting.
bool plain(const std::string& text, const char* extra) {
  for (char c : text)
    if (!std::isalnum(static_cast<unsigned char>(c)) && !std::strchr(extra, c)) return false;
  return true;
}

template <class Stream>
void serialise(Stream& s, Hello& m) {
  s.u32(m.magic);
  s.u16(m.version);
  s.text(m.client_name, kMaxName);
}

template <class Stream>
void serialise(Stream& s, Welcome& m) {
  s.u16(m.version);
  s.text(m.server_name, kMaxName);
}

template <class Stream>
void serialise(Stream& s, ErrorMessage& m) {
  enumeration(s, m.code, 1, 12, "error code");
  s.text(m.reason, kMaxReason);
}

template <class Stream>
void serialise(Stream& s, Ping& m) {
  s.u64(m.nonce);
}

template <class Stream>
void serialise(Stream& s, Pong& m) {
  s.u64(m.nonce);
}

template <class Stream>
void serialise(Stream& s, Join& m) {
  s.text(m.session, kMaxName);
  s.text(m.token, kMaxToken);
  flag(s, m.open_room, "join open room");
  if constexpr (Stream::reading) check(!m.session.empty() && plain(m.session, "-_."), "session name must be letters, digits, - _ .");
}

template <class Stream>
void serialise(Stream&, Leave&) {}

template <class Stream>
void serialise(Stream& s, StyleChange& m) {
  s.text(m.renderer, kMaxRenderer);
  const size_t n = s.count(m.settings.size(), kMaxSettings, "style settings");
  if constexpr (Stream::reading) m.settings.resize(n);
  for (std::string& setting : m.settings) {
    s.text(setting, kMaxSetting);
    if constexpr (Stream::reading) {
      const size_t eq = setting.find('=');
      check(eq != std::string::npos && eq > 0 && plain(setting.substr(0, eq), "_-"), "style setting is not KEY=VALUE");
    }
  }
  if constexpr (Stream::reading) check(!m.renderer.empty() && plain(m.renderer, "-_+"), "renderer name must be letters, digits, - _ +");
}

template <class Stream>
void serialise(Stream& s, CameraPose& m) {
  s.u32(m.sequence);
  s.vec3(m.position);
  s.vec3(m.target);
  s.vec3(m.up);
  s.f32(m.fov_y_degrees);
  if constexpr (Stream::reading) {
    check(m.fov_y_degrees >= 1.0f && m.fov_y_degrees <= 170.0f, "camera field of view outside 1..170 degrees");
    check(glm::length(m.up) > 1e-6f, "camera up vector is zero");
    check(glm::length(m.position - m.target) > 1e-6f, "camera position equals its target");
    check(glm::length(m.position) < 1e6f && glm::length(m.target) < 1e6f, "camera outside the +-1e6 world");
  }
}

template <class Stream>
void serialise(Stream& s, ObjectPose& m) {
  s.u32(m.sequence);
  s.f32(m.rotation.x), s.f32(m.rotation.y), s.f32(m.rotation.z), s.f32(m.rotation.w);
  s.vec3(m.translation);
  s.f32(m.scale);
  if constexpr (Stream::reading) {
    check(std::abs(glm::length(m.rotation) - 1.0f) < 1e-3f, "object rotation is not a unit quaternion");
    check(m.scale > 1e-6f && m.scale < 1e6f, "object scale outside 1e-6..1e6");
    check(glm::length(m.translation) < 1e6f, "object outside the +-1e6 world");
  }
}

template <class Stream>
void serialise(Stream& s, ExpressionCode& m) {
  s.u8(m.code);
  s.u8(m.intensity);
  s.u16(m.sequence);
  for (int8_t& p : m.params) {
    auto raw = uint8_t(p);
    s.u8(raw);
    p = int8_t(raw);
  }
}

template <class Stream>
void serialise(Stream& s, TweenData& m) {
  s.u16(m.pair);
  s.blob(m.data, kMaxTween);
}

template <class Stream>
void serialise(Stream& s, AssetAnnounce& m) {
  s.hash(m.hash);
  s.u64(m.size);
  enumeration(s, m.kind, 1, kAssetKinds, "asset kind");
  s.text(m.name, kMaxName);
  if constexpr (Stream::reading) {
    check(m.size <= kMaxAssetBytes, "asset larger than 1 GiB");
    check(!m.name.empty() && m.name[0] != '.' && plain(m.name, "-_."), "asset name must be a plain file name");
  }
}

template <class Stream>
void serialise(Stream& s, AssetRequest& m) {
  s.hash(m.hash);
  s.u64(m.offset);
  s.u32(m.length);
  if constexpr (Stream::reading) check(m.length > 0 && m.length <= kMaxChunk && m.offset <= kMaxAssetBytes, "asset request outside 1..65536 bytes");
}

template <class Stream>
void serialise(Stream& s, AssetChunk& m) {
  s.hash(m.hash);
  s.u64(m.offset);
  s.blob(m.data, kMaxChunk);
  if constexpr (Stream::reading) check(m.offset + m.data.size() <= kMaxAssetBytes, "asset chunk beyond 1 GiB");
}

template <class Stream>
void serialise(Stream& s, Product& m) {
  s.u16(m.width);
  s.u16(m.height);
  const size_t n = s.count(m.directions.size(), kMaxProductSamples, "product samples");
  if constexpr (Stream::reading) m.directions.resize(n);
  for (glm::vec3& d : m.directions) {
    // Unit vectors as 3 x i16 (component x 32767), as in the tween data's header.
    std::array<uint16_t, 3> q{};
    if constexpr (!Stream::reading)
      for (int k = 0; k < 3; ++k) q[size_t(k)] = uint16_t(int16_t(std::lround(std::clamp(d[k], -1.0f, 1.0f) * 32767.0f)));
    for (uint16_t& v : q) s.u16(v);
    if constexpr (Stream::reading) {
      // Clamped as the tween data's directions are: -32768 reads as -1, so what was read writes back the same.
      for (int k = 0; k < 3; ++k) d[k] = std::max(-1.0f, float(int16_t(q[size_t(k)])) / 32767.0f);
      check(std::abs(glm::length(d) - 1.0f) < 0.01f, "product sample direction is not a unit vector");
    }
  }
  s.u16(m.cells);
  s.f32(m.distance_diagonals);
  s.f32(m.fov_y_degrees);
  const size_t levels = s.count(m.levels.size(), kMaxZoomLevels, "zoom levels");
  if constexpr (Stream::reading) m.levels.resize(levels);
  for (ImageSize& level : m.levels) {
    s.u16(level.width);
    s.u16(level.height);
  }
  if constexpr (Stream::reading) {
    const bool empty = m.directions.empty();
    ImageSize below{m.width, m.height};
    for (const ImageSize& level : m.levels) {
      check(!empty && level.width > below.width && level.height > below.height && level.width <= 4095 && level.height <= 4095,
            "a zoom level is not larger than the one below it, or over 4095");
      below = level;
    }
    check(empty ? m.width == 0 && m.height == 0 && m.cells == 0 : m.directions.size() >= 2, "product with fewer than 2 samples");
    check(empty || (m.width >= 1 && m.height >= 1 && m.width <= 4095 && m.height <= 4095), "product image size outside 1..4095");
    check(m.cells <= 4 * kMaxProductSamples, "product has too many tween cells");
    check(m.distance_diagonals > 0.01f && m.distance_diagonals < 1000.0f, "product camera distance outside 0.01..1000 diagonals");
    check(m.fov_y_degrees >= 1.0f && m.fov_y_degrees <= 170.0f, "product field of view outside 1..170 degrees");
  }
}

template <class Stream>
void serialise(Stream& s, Snapshot& m) {
  s.text(m.session, kMaxName);
  enumeration(s, m.kind, 1, 3, "session kind");
  s.u32(m.revision);
  const size_t n = s.count(m.assets.size(), kMaxAssets, "assets");
  if constexpr (Stream::reading) m.assets.resize(n);
  for (AssetAnnounce& a : m.assets) serialise(s, a);
  serialise(s, m.style);
  serialise(s, m.camera);
  serialise(s, m.object);
  serialise(s, m.expression);
  serialise(s, m.product);
}

template <class Stream>
void serialise(Stream& s, Publish& m) {
  flag(s, m.camera, "publish camera");
  flag(s, m.microphone, "publish microphone");
}

template <class Stream>
void serialise(Stream& s, NeutralPhoto& m) {
  s.blob(m.jpeg, kMaxPhotoBytes);
}

template <class Stream>
void serialise(Stream& s, FaceCrop& m) {
  s.u32(m.time_ms);
  for (uint16_t* v : {&m.frame_width, &m.frame_height, &m.x, &m.y, &m.width, &m.height}) s.u16(*v);
  s.blob(m.jpeg, kMaxCropBytes);
  if constexpr (Stream::reading) {
    check(m.frame_width >= 16 && m.frame_height >= 16 && m.frame_width <= 4096 && m.frame_height <= 4096, "face crop: frame size outside 16..4096");
    check(m.width >= 8 && m.height >= 8 && uint32_t(m.x) + m.width <= m.frame_width && uint32_t(m.y) + m.height <= m.frame_height,
          "face crop: rectangle outside its frame");
  }
}

template <class Stream>
void serialise(Stream& s, FaceVideo& m) {
  s.u32(m.time_ms);
  s.u32(m.sequence);
  for (uint16_t* v : {&m.frame_width, &m.frame_height, &m.x, &m.y, &m.width, &m.height}) s.u16(*v);
  flag(s, m.key, "face video key");
  s.blob(m.vp8, kMaxVideoFrameBytes);
  if constexpr (Stream::reading) {
    check(m.frame_width >= 16 && m.frame_height >= 16 && m.frame_width <= 4096 && m.frame_height <= 4096, "face video: frame size outside 16..4096");
    check(m.width >= 8 && m.height >= 8 && uint32_t(m.x) + m.width <= m.frame_width && uint32_t(m.y) + m.height <= m.frame_height,
          "face video: rectangle outside its frame");
    check(!m.vp8.empty(), "empty face video frame");
  }
}

template <class Stream>
void serialise(Stream&, KeyFrameRequest&) {}

template <class Stream>
void serialise(Stream& s, VoiceRoute& m) {
  s.text(m.ticket, kVoiceTicketChars);
  if constexpr (Stream::reading)
    check(m.ticket.size() == kVoiceTicketChars && m.ticket.find_first_not_of("0123456789abcdef") == std::string::npos,
          "voice route: the ticket is not 32 hex digits");
}

template <class Stream>
void serialise(Stream& s, FaceRegion& m) {
  flag(s, m.found, "face region found");
  for (uint16_t* v : {&m.x, &m.y, &m.width, &m.height}) s.u16(*v);
}

template <class Stream>
void serialise(Stream& s, VoiceFrame& m) {
  s.u16(m.member);
  s.u32(m.time_ms);
  s.blob(m.opus, kMaxVoiceBytes);
  if constexpr (Stream::reading) check(!m.opus.empty(), "empty voice frame");
}

template <class Stream>
void serialise(Stream& s, MemberFace& m) {
  s.u16(m.member);
  s.u32(m.time_ms);
  // The code and its intensity only: a call's faces come several times a second, and the
  // sequence and parameters of the session-wide code say nothing here (time_ms orders them).
  s.u8(m.expression.code);
  s.u8(m.expression.intensity);
  for (int8_t* v : {&m.yaw, &m.pitch, &m.roll}) {
    auto raw = uint8_t(*v);
    s.u8(raw);
    *v = int8_t(raw);
  }
  enumeration(s, m.source, 0, 2, "face source");
}

// A layer's code and intensity: only codes that layer takes (common/face/face_layers.hpp).
template <class Stream>
void layer(Stream& s, ExpressionState& v, bool (*takes)(Expression), const char* what) {
  auto code = uint8_t(v.expression);
  s.u8(code);
  s.u8(v.intensity);
  if constexpr (Stream::reading) {
    const auto e = expression_from_code(code);
    if (!e || !takes(*e)) throw ProtocolError(std::string(what) + " code " + std::to_string(code) + " is not one that layer takes");
    v.expression = *e;
  }
}

template <class Stream>
void serialise(Stream& s, MemberLayers& m) {
  s.u16(m.member);
  s.u32(m.time_ms);
  for (int8_t* v : {&m.yaw, &m.pitch, &m.roll}) {
    auto raw = uint8_t(*v);
    s.u8(raw);
    *v = int8_t(raw);
    if constexpr (Stream::reading) check(std::abs(int(*v)) <= kMaxPoseDegrees, "member layers: head pose outside +-90 degrees");
  }
  layer(s, m.expression, expression_layer_takes, "member layers: expression");
  layer(s, m.mouth, mouth_layer_takes, "member layers: mouth");
  s.u8(m.eye_left);
  s.u8(m.eye_right);
  if constexpr (Stream::reading) check(m.eye_left <= kMaxEyeOpenness && m.eye_right <= kMaxEyeOpenness, "member layers: eye openness over 200%");
  enumeration(s, m.source, 0, 2, "face source");
}

template <class Stream>
void serialise(Stream& s, CallMember& m) {
  s.u16(m.member);
  s.text(m.name, kMaxName);
  flag(s, m.camera, "member camera");
  flag(s, m.microphone, "member microphone");
  flag(s, m.speaking, "member speaking");
  flag(s, m.face_found, "member face found");
  const size_t n = s.count(m.assets.size(), 2, "member assets");
  if constexpr (Stream::reading) m.assets.resize(n);
  for (AssetAnnounce& a : m.assets) serialise(s, a);
  if constexpr (Stream::reading) check(m.member != 0, "member number 0");
}

template <class Stream>
void serialise(Stream& s, Roster& m) {
  s.u16(m.you);
  const size_t n = s.count(m.members.size(), kMaxMembers, "call members");
  if constexpr (Stream::reading) m.members.resize(n);
  for (CallMember& member : m.members) serialise(s, member);
  s.u16(m.host);
  flag(s, m.locked, "roster locked");
}

template <class Stream>
void serialise(Stream& s, HostKey& m) {
  s.text(m.key, kHostKeyChars);
  if constexpr (Stream::reading)
    check(m.key.size() == kHostKeyChars && m.key.find_first_not_of("0123456789abcdef") == std::string::npos, "host key is not 32 hex digits");
}

template <class Stream>
void serialise(Stream& s, RoomControl& m) {
  enumeration(s, m.action, 1, 3, "room action");
  s.u16(m.member);
  if constexpr (Stream::reading) check(m.action == RoomAction::Remove ? m.member != 0 : m.member == 0, "room control names a member only to remove");
}

template <class Stream>
void serialise(Stream& s, Permissions& m) {
  const size_t n = s.count(m.refused.size(), 4, "refused changes");
  if constexpr (Stream::reading) m.refused.resize(n);
  for (Permissions::Refused& r : m.refused) {
    enumeration(s, r.change, unsigned(MessageType::StyleChange), unsigned(MessageType::ExpressionCode), "refused change");
    s.text(r.reason, kMaxReason);
  }
}

// Runs a message's serialise function over a writing or measuring stream. The streams take
// fields by reference so one function serves reading too; writing and measuring never change them.
template <class Stream>
void serialise_message(Stream& s, const Message& message) {
  std::visit([&](const auto& m) { serialise(s, const_cast<std::remove_const_t<std::remove_reference_t<decltype(m)>>&>(m)); }, message);
}

template <size_t... I>
Message decode_alternative(size_t index, ReadStream& s, std::index_sequence<I...>) {
  Message m;
  // Picks the alternative whose index matches and reads it in place.
  (void)((I == index ? (m.emplace<I>(), serialise(s, std::get<I>(m)), true) : false) || ...);
  return m;
}

}  // namespace

std::string to_string(SessionKind kind) {
  switch (kind) {
    case SessionKind::Scene: return "scene";
    case SessionKind::Turntable: return "turntable";
    case SessionKind::Conference: return "conference";
  }
  return "unknown";
}

SessionKind session_kind_from_string(const std::string& name) {
  for (SessionKind k : {SessionKind::Scene, SessionKind::Turntable, SessionKind::Conference})
    if (to_string(k) == name) return k;
  throw Error("session kind '" + name + "' is not scene, turntable or conference");
}

std::string to_string(AssetKind kind) {
  static const char* names[] = {"mesh", "image", "samples", "tween", "landmarks", "matte", "zoom"};
  return unsigned(kind) >= 1 && unsigned(kind) <= kAssetKinds ? names[unsigned(kind) - 1] : "unknown";
}

MessageType type_of(const Message& m) { return MessageType(m.index() + 1); }

const char* name_of(MessageType type) {
  static const char* names[] = {"hello", "welcome", "error", "ping", "pong", "join", "leave", "snapshot",
                                "style-change", "camera-pose", "object-pose", "expression-code", "tween-data",
                                "asset-announce", "asset-request", "asset-chunk", "publish", "neutral-photo",
                                "face-crop", "face-region", "voice-frame", "member-face", "roster", "permissions",
                                "face-video", "key-frame-request", "voice-route", "host-key", "room-control", "member-layers"};
  const auto i = unsigned(type);
  return i >= 1 && i <= kMessageTypes ? names[i - 1] : "unknown";
}

bool is_state(MessageType type) {
  return type == MessageType::StyleChange || type == MessageType::CameraPose || type == MessageType::ObjectPose ||
         type == MessageType::ExpressionCode || type == MessageType::Snapshot || type == MessageType::Roster;
}

bool apply_state_change(Snapshot& s, const Message& m) {
  if (const auto* style = std::get_if<StyleChange>(&m)) s.style = *style;
  else if (const auto* camera = std::get_if<CameraPose>(&m)) s.camera = *camera;
  else if (const auto* object = std::get_if<ObjectPose>(&m)) s.object = *object;
  else if (const auto* expression = std::get_if<ExpressionCode>(&m)) s.expression = *expression;
  else return false;
  ++s.revision;
  return true;
}

Bytes encode(const Message& message) {
  Bytes out(kHeaderBytes);
  WriteStream s(out);
  serialise_message(s, message);
  const size_t payload = out.size() - kHeaderBytes;
  if (payload > kMaxPayload) throw ProtocolError(std::string(name_of(type_of(message))) + " message exceeds the frame limit");
  const auto type = uint16_t(type_of(message));
  for (int i = 0; i < 4; ++i) out[size_t(i)] = uint8_t(payload >> (8 * i));
  out[4] = uint8_t(type), out[5] = uint8_t(type >> 8);
  return out;
}

size_t encoded_size(const Message& message) {
  MeasureStream s;
  serialise_message(s, message);
  return kHeaderBytes + s.bytes;
}

Message decode(MessageType type, const uint8_t* payload, size_t size) {
  if (unsigned(type) < 1 || unsigned(type) > kMessageTypes) throw ProtocolError("unknown message type " + std::to_string(unsigned(type)));
  if (size > kMaxPayload) throw ProtocolError("payload exceeds the frame limit");
  ReadStream s(payload, size);
  Message m = decode_alternative(size_t(type) - 1, s, std::make_index_sequence<std::variant_size_v<Message>>{});
  s.finish();
  return m;
}

std::optional<ExpressionState> expression_state(const ExpressionCode& message) {
  const auto expression = expression_from_code(message.code);
  if (!expression) return std::nullopt;
  return ExpressionState{*expression, message.intensity};
}

}  // namespace inkwire::protocol
