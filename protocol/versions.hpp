#pragma once
// What a peer of an older version than ours (kOldestVersion .. kVersion - 1) reads and writes
// instead (protocol/SPEC.md, "Versioning"). The server speaks each peer's version at the edge of
// its connection, so the rest of it deals in this version's messages only:
// - version 7 knows message types up to 27, 8 up to 29: a newer type is not sent to it (a
//   member's face goes as member-face instead: protocol/face_versions.hpp), nor read from it;
// - version 7 wrote join without open_room and reads the roster without host and locked (both
//   the last fields of their message), and errors only up to 10: 11 (locked) and 12 (removed)
//   reach it as 9 (refused), with the same reason.
#include <cstdint>
#include <memory>

#include "protocol/messages.hpp"

namespace inkwire::protocol {

inline constexpr uint16_t kRoomsVersion = 8;   // join's open_room, the roster's host and locked, messages 28-29, errors 11-12
inline constexpr uint16_t kLayersVersion = 9;  // member-layers (message 30)

// The message types a peer of `version` knows: 1 .. this.
uint16_t message_types_of(uint16_t version);

// The frame a peer of `version` reads for this version's `frame` of `type`: the same frame when
// nothing differs, another one, or nullptr when that peer has no such message.
std::shared_ptr<const Bytes> frame_for(uint16_t version, std::shared_ptr<const Bytes> frame, MessageType type);

// Reads a payload a peer of `version` wrote as this version's message; throws ProtocolError as
// decode() does, and for a type that peer's version does not have.
Message decode_from(uint16_t version, MessageType type, const uint8_t* payload, size_t size);

}  // namespace inkwire::protocol
