#include "protocol/streams.hpp"

namespace inkwire::protocol {

size_t WriteStream::count(size_t n, size_t max, const char* what) {
  if (n > max) throw ProtocolError(std::string("too many ") + what + ": " + std::to_string(n) + " > " + std::to_string(max));
  u16(uint16_t(n));
  return n;
}

void WriteStream::counted(const void* data, size_t size, size_t max, int width) {
  if (size > max) throw ProtocolError("field of " + std::to_string(size) + " bytes exceeds its limit of " + std::to_string(max));
  put(size, width);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out_.insert(out_.end(), bytes, bytes + size);
}

void ReadStream::need(size_t bytes) const {
  if (size_t(end_ - p_) < bytes)
    throw ProtocolError("message truncated: needs " + std::to_string(bytes) + " more bytes, has " + std::to_string(end_ - p_));
}

uint64_t ReadStream::get(int bytes) {
  need(size_t(bytes));
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= uint64_t(p_[i]) << (8 * i);
  p_ += bytes;
  return v;
}

void ReadStream::f32(float& v) {
  const auto bits = uint32_t(get(4));
  std::memcpy(&v, &bits, 4);
  if (!std::isfinite(v)) throw ProtocolError("a float field is not finite");
}

void ReadStream::text(std::string& v, size_t max) {
  const size_t size = get(2);
  if (size > max) throw ProtocolError("text of " + std::to_string(size) + " bytes exceeds its limit of " + std::to_string(max));
  need(size);
  v.assign(reinterpret_cast<const char*>(p_), size);
  p_ += size;
  // Texts are names, parameters and reasons: printable ASCII and UTF-8, never control bytes.
  for (unsigned char c : v)
    if (c < 0x20 || c == 0x7f) throw ProtocolError("text field holds a control byte");
}

void ReadStream::blob(Bytes& v, size_t max) {
  const size_t size = get(4);
  if (size > max) throw ProtocolError("blob of " + std::to_string(size) + " bytes exceeds its limit of " + std::to_string(max));
  need(size);
  v.assign(p_, p_ + size);
  p_ += size;
}

void ReadStream::hash(Hash& v) {
  need(v.size());
  std::memcpy(v.data(), p_, v.size());
  p_ += v.size();
}

size_t ReadStream::count(size_t, size_t max, const char* what) {
  const size_t n = get(2);
  if (n > max) throw ProtocolError(std::string("too many ") + what + ": " + std::to_string(n) + " > " + std::to_string(max));
  return n;
}

void ReadStream::finish() const {
  if (p_ != end_) throw ProtocolError("message has " + std::to_string(end_ - p_) + " trailing bytes");
}

}  // namespace inkwire::protocol
