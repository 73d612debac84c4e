// Older peers' wire (protocol/versions.hpp): the few fields that differ, at the edge.
#include "protocol/versions.hpp"

#include <string>

#include "protocol/framing.hpp"

namespace inkwire::protocol {
namespace {

// Version 8 (kRoomsVersion) appended to the roster its host (u16) and locked (u8).
constexpr size_t kRosterRoomBytes = 3;

ErrorCode error_code_for(uint16_t version, ErrorCode code) {
  if (version < kRoomsVersion && (code == ErrorCode::Locked || code == ErrorCode::Removed)) return ErrorCode::Refused;
  return code;
}

}  // namespace

uint16_t message_types_of(uint16_t version) {
  if (version >= kVersion) return kMessageTypes;
  return version >= kRoomsVersion ? uint16_t(MessageType::RoomControl) : uint16_t(MessageType::VoiceRoute);
}

std::shared_ptr<const Bytes> frame_for(uint16_t version, std::shared_ptr<const Bytes> frame, MessageType type) {
  if (version >= kVersion) return frame;
  if (uint16_t(type) > message_types_of(version)) return nullptr;
  if (version >= kRoomsVersion) return frame;
  if (type == MessageType::Roster) {
    // The same bytes without the last fields; the header's length says so.
    auto older = std::make_shared<Bytes>(frame->begin(), frame->end() - kRosterRoomBytes);
    const auto payload = uint32_t(older->size() - kHeaderBytes);
    for (int i = 0; i < 4; ++i) (*older)[size_t(i)] = uint8_t(payload >> (8 * i));
    return older;
  }
  if (type == MessageType::Error) {
    auto error = std::get<ErrorMessage>(decode_frame(frame->data(), frame->size()));
    const ErrorCode code = error_code_for(version, error.code);
    if (code == error.code) return frame;
    error.code = code;
    return std::make_shared<const Bytes>(encode(error));
  }
  return frame;
}

Message decode_from(uint16_t version, MessageType type, const uint8_t* payload, size_t size) {
  if (version < kVersion && uint16_t(type) > message_types_of(version))
    throw ProtocolError("message type " + std::to_string(unsigned(type)) + " is not in protocol version " + std::to_string(version));
  if (version < kRoomsVersion && type == MessageType::Join) {
    // Joins before version 8 end before open_room: they never open a room.
    if (size > kMaxPayload) throw ProtocolError("payload exceeds the frame limit");
    Bytes with_open_room(payload, payload + size);
    with_open_room.push_back(0);
    return decode(type, with_open_room.data(), with_open_room.size());
  }
  return decode(type, payload, size);
}

}  // namespace inkwire::protocol
