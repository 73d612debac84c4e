#include "protocol/framing.hpp"

namespace inkwire::protocol {

FrameHeader parse_header(const uint8_t* h) {
  FrameHeader header;
  header.length = uint32_t(h[0]) | uint32_t(h[1]) << 8 | uint32_t(h[2]) << 16 | uint32_t(h[3]) << 24;
  const auto type = uint16_t(h[4] | h[5] << 8);
  if (type < 1 || type > kMessageTypes) throw ProtocolError("unknown message type " + std::to_string(type));
  if (header.length > kMaxPayload)
    throw ProtocolError("frame of " + std::to_string(header.length) + " bytes exceeds the limit of " + std::to_string(kMaxPayload));
  header.type = MessageType(type);
  return header;
}

Message decode_frame(const uint8_t* frame, size_t size) {
  if (size < kHeaderBytes) throw ProtocolError("a frame of " + std::to_string(size) + " bytes has no whole header");
  const FrameHeader header = parse_header(frame);
  if (header.length != size - kHeaderBytes)
    throw ProtocolError("frame says " + std::to_string(header.length) + " payload bytes, holds " + std::to_string(size - kHeaderBytes));
  return decode(header.type, frame + kHeaderBytes, header.length);
}

void FrameDecoder::feed(const uint8_t* data, size_t size) {
  // Drop consumed bytes before growing, so the buffer never holds more than one frame plus the
  // piece just fed.
  if (start_ > 0 && start_ == buffer_.size()) buffer_.clear(), start_ = 0;
  if (start_ > kMaxPayload) buffer_.erase(buffer_.begin(), buffer_.begin() + std::ptrdiff_t(start_)), start_ = 0;
  buffer_.insert(buffer_.end(), data, data + size);
  check_header();
}

void FrameDecoder::check_header() {
  if (buffered() >= kHeaderBytes) parse_header(buffer_.data() + start_);
}

std::optional<Message> FrameDecoder::next() {
  if (buffered() < kHeaderBytes) return std::nullopt;
  const FrameHeader header = parse_header(buffer_.data() + start_);
  if (buffered() < kHeaderBytes + header.length) return std::nullopt;
  const uint8_t* payload = buffer_.data() + start_ + kHeaderBytes;
  start_ += kHeaderBytes + header.length;
  Message m = decode(header.type, payload, header.length);
  check_header();
  return m;
}

void FrameDecoder::finish() const {
  if (buffered() > 0) throw ProtocolError("stream ended inside a message (" + std::to_string(buffered()) + " bytes left)");
}

}  // namespace inkwire::protocol
