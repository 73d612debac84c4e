#pragma once
// Length framing (protocol/SPEC.md): every message travels as
//   u32 payload length | u16 message type | payload
// The length is checked against kMaxPayload and the type against the known ones before a byte
// of payload is allocated or read.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "protocol/messages.hpp"

namespace inkwire::protocol {

inline constexpr size_t kHeaderBytes = 6;
inline constexpr size_t kMaxPayload = 128 * 1024;

struct FrameHeader {
  uint32_t length = 0;
  MessageType type = MessageType::Hello;
};

// Throws ProtocolError for an unknown type or a length above kMaxPayload.
FrameHeader parse_header(const uint8_t* header);

// The whole frame (header + payload). Throws ProtocolError if a field exceeds its limit.
Bytes encode(const Message& message);
// Bytes encode() would produce, without producing them.
size_t encoded_size(const Message& message);
// Reads one payload; throws ProtocolError on any malformed, out-of-range or trailing byte.
Message decode(MessageType type, const uint8_t* payload, size_t size);
// Reads one whole frame (header and payload) held in memory, e.g. a stored one; throws
// ProtocolError unless it is exactly one valid frame.
Message decode_frame(const uint8_t* frame, size_t size);

// Splits a byte stream that arrives in arbitrary pieces into messages.
class FrameDecoder {
 public:
  // Appends bytes; throws ProtocolError as soon as a header is bad (before buffering its body).
  void feed(const uint8_t* data, size_t size);
  // The next complete message, if one has arrived; throws ProtocolError if it is malformed.
  std::optional<Message> next();
  // At the end of the stream: throws ProtocolError if part of a message is left over.
  void finish() const;
  size_t buffered() const { return buffer_.size() - start_; }

 private:
  void check_header();
  Bytes buffer_;
  size_t start_ = 0;
};

}  // namespace inkwire::protocol
