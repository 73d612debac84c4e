#include "server/relay/broker_formats.hpp"

#include <charconv>

#include "common/error.hpp"
#include "protocol/framing.hpp"

namespace inkwire::server {
namespace {

using protocol::ProtocolError;

std::string counted(const std::string& s) { return std::to_string(s.size()) + ":" + s; }

// Reads numbers and counted names off the front of a text.
struct Reader {
  std::string_view rest;
  uint64_t number(char end, const char* what) {
    uint64_t out = 0;
    const auto [p, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), out);
    if (ec != std::errc() || p == rest.data() + rest.size() || *p != end) throw ProtocolError(std::string("broker text: no ") + what);
    rest.remove_prefix(size_t(p - rest.data()) + 1);
    return out;
  }
  std::string name(const char* what) {
    const uint64_t n = number(':', what);
    if (n > rest.size() || n > protocol::kMaxName * 4) throw ProtocolError(std::string("broker text: ") + what + " longer than what is left");
    std::string out(rest.substr(0, n));
    rest.remove_prefix(n);
    return out;
  }
  protocol::Message frame() { return protocol::decode_frame(reinterpret_cast<const uint8_t*>(rest.data()), rest.size()); }
  std::string bytes(size_t max, const char* what) {
    const uint64_t n = number(':', what);
    if (n > rest.size() || n > max) throw ProtocolError(std::string("broker text: ") + what + " longer than what is left or allowed");
    std::string out(rest.substr(0, n));
    rest.remove_prefix(n);
    return out;
  }
};

}  // namespace

std::string call_share(const CallShare& share) {
  if (share.removal)
    return "R" + counted(share.origin) + counted(share.session) + counted(share.removal->instance) + std::to_string(share.removal->member) + " " +
           counted(share.removal->reason);
  std::string out = (share.message ? "M" : "P") + counted(share.origin) + counted(share.session);
  if (share.message) {
    const protocol::Bytes frame = protocol::encode(*share.message);
    return out + std::string(frame.begin(), frame.end());
  }
  return out + std::to_string(share.photo_member) + " " + counted(std::string(share.photo.begin(), share.photo.end())) + counted(share.landmarks);
}

CallShare parse_call_share(std::string_view text) {
  if (text.empty() || (text[0] != 'M' && text[0] != 'P' && text[0] != 'R')) throw ProtocolError("broker text: not a call share");
  Reader r{text.substr(1)};
  CallShare share;
  share.origin = r.name("origin");
  share.session = r.name("session");
  if (text[0] == 'R') {
    CallShare::Removal removal;
    removal.instance = r.name("instance");
    const uint64_t member = r.number(' ', "member");
    if (member == 0 || member > 65535) throw ProtocolError("broker text: member number outside 1..65535");
    removal.member = uint16_t(member);
    removal.reason = r.bytes(protocol::kMaxReason, "reason");
    if (!r.rest.empty()) throw ProtocolError("broker text: bytes after a removal");
    share.removal = std::move(removal);
    return share;
  }
  if (text[0] == 'M') {
    share.message = r.frame();
    const auto type = protocol::type_of(*share.message);
    if (type != protocol::MessageType::VoiceFrame && type != protocol::MessageType::MemberFace && type != protocol::MessageType::MemberLayers &&
        type != protocol::MessageType::Roster)
      throw ProtocolError(std::string("broker text: a call does not share a ") + protocol::name_of(type));
    return share;
  }
  const uint64_t member = r.number(' ', "member");
  if (member == 0 || member > 65535) throw ProtocolError("broker text: member number outside 1..65535");
  share.photo_member = uint16_t(member);
  const std::string photo = r.bytes(protocol::kMaxPhotoBytes, "photo");
  share.photo.assign(photo.begin(), photo.end());
  share.landmarks = r.bytes(64 * 1024, "landmarks");
  if (!r.rest.empty()) throw ProtocolError("broker text: bytes after a call's photo");
  return share;
}

std::string state_field(const protocol::Message& change) {
  switch (protocol::type_of(change)) {
    case protocol::MessageType::StyleChange: return "style";
    case protocol::MessageType::CameraPose: return "camera";
    case protocol::MessageType::ObjectPose: return "object";
    case protocol::MessageType::ExpressionCode: return "expression";
    default: throw ProtocolError(std::string("a ") + protocol::name_of(protocol::type_of(change)) + " is not session state");
  }
}

std::string event_header(int64_t published_us, uint64_t sender, const std::string& origin, const std::string& session) {
  return std::to_string(published_us) + " " + std::to_string(sender) + " " + counted(origin) + counted(session);
}

BrokerEvent parse_event(std::string_view payload) {
  Reader r{payload};
  BrokerEvent e;
  const uint64_t revision = r.number(' ', "revision");
  if (revision > UINT32_MAX) throw ProtocolError("broker text: revision out of range");
  e.revision = uint32_t(revision);
  e.published_us = int64_t(r.number(' ', "time") & INT64_MAX);
  e.sender = r.number(' ', "sender");
  e.origin = r.name("origin");
  e.session = r.name("session");
  e.change = r.frame();
  state_field(e.change);  // only state changes travel this way
  return e;
}

// Who made the session comes first, marked by '@' (definitions from before sessions people make
// have no mark: the operator's).
std::string session_definition(const StoredSession& stored) {
  const protocol::Bytes frame = protocol::encode(stored.state);
  return "@" + counted(to_string(stored.maker)) + counted(stored.creator) + (stored.kept ? "1" : "0") + counted(stored.token) +
         counted(stored.editor_token) + std::string(frame.begin(), frame.end());
}

StoredSession parse_session_definition(std::string_view text) {
  Reader r{text};
  StoredSession stored;
  if (!r.rest.empty() && r.rest.front() == '@') {
    r.rest.remove_prefix(1);
    try {
      stored.maker = made_by_from_string(r.name("maker"));
    } catch (const Error& e) {
      throw ProtocolError(std::string("broker text: ") + e.what());
    }
    stored.creator = r.name("creator");
    if (r.rest.empty() || (r.rest.front() != '0' && r.rest.front() != '1')) throw ProtocolError("broker text: no kept flag");
    stored.kept = r.rest.front() == '1';
    r.rest.remove_prefix(1);
  }
  stored.token = r.name("token");
  stored.editor_token = r.name("editor token");
  protocol::Message message = r.frame();
  auto* snapshot = std::get_if<protocol::Snapshot>(&message);
  if (!snapshot) throw ProtocolError("broker text: a session's definition holds no snapshot");
  stored.state = std::move(*snapshot);
  return stored;
}

}  // namespace inkwire::server
