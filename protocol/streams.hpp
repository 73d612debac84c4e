#pragma once
// The three streams a message's one serialise function runs over (protocol/SPEC.md):
// WriteStream appends bytes, ReadStream parses them with every length and range checked before
// use, MeasureStream counts bytes. A serialise function is written once against this interface:
//
//   template <class Stream> void serialise(Stream& s, CameraPose& m) { s.u32(m.sequence); ... }
//
// Integers and floats are little-endian; floats are IEEE-754 binary32 and must be finite.
// ReadStream throws ProtocolError (a one-line reason) on anything out of bounds.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "common/error.hpp"

namespace inkwire::protocol {

class ProtocolError : public Error {
 public:
  using Error::Error;
};

using Bytes = std::vector<uint8_t>;
using Hash = std::array<uint8_t, 32>;  // SHA-256 of an asset's bytes

class WriteStream {
 public:
  static constexpr bool reading = false;
  explicit WriteStream(Bytes& out) : out_(out) {}

  void u8(uint8_t v) { out_.push_back(v); }
  void u16(uint16_t v) { put(v, 2); }
  void u32(uint32_t v) { put(v, 4); }
  void u64(uint64_t v) { put(v, 8); }
  void f32(float v) {
    uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    u32(bits);
  }
  void vec3(glm::vec3 v) { f32(v.x), f32(v.y), f32(v.z); }
  // A byte count below `max` as u16 (texts) or u32 (blobs), then the bytes.
  void text(std::string& v, size_t max) { counted(v.data(), v.size(), max, 2); }
  void blob(Bytes& v, size_t max) { counted(v.data(), v.size(), max, 4); }
  void hash(Hash& v) { out_.insert(out_.end(), v.begin(), v.end()); }
  // A list's element count (u16), checked against its limit.
  size_t count(size_t n, size_t max, const char* what);

 private:
  void put(uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) out_.push_back(uint8_t(v >> (8 * i)));
  }
  void counted(const void* data, size_t size, size_t max, int width);
  Bytes& out_;
};

class ReadStream {
 public:
  static constexpr bool reading = true;
  ReadStream(const uint8_t* data, size_t size) : p_(data), end_(data + size) {}

  void u8(uint8_t& v) { v = uint8_t(get(1)); }
  void u16(uint16_t& v) { v = uint16_t(get(2)); }
  void u32(uint32_t& v) { v = uint32_t(get(4)); }
  void u64(uint64_t& v) { v = get(8); }
  void f32(float& v);
  void vec3(glm::vec3& v) { f32(v.x), f32(v.y), f32(v.z); }
  void text(std::string& v, size_t max);
  void blob(Bytes& v, size_t max);
  void hash(Hash& v);
  size_t count(size_t n, size_t max, const char* what);
  // Throws unless every byte was consumed (trailing bytes mean a malformed message).
  void finish() const;

 private:
  uint64_t get(int bytes);
  void need(size_t bytes) const;
  const uint8_t* p_;
  const uint8_t* end_;
};

class MeasureStream {
 public:
  static constexpr bool reading = false;
  void u8(uint8_t) { bytes += 1; }
  void u16(uint16_t) { bytes += 2; }
  void u32(uint32_t) { bytes += 4; }
  void u64(uint64_t) { bytes += 8; }
  void f32(float) { bytes += 4; }
  void vec3(glm::vec3) { bytes += 12; }
  void text(std::string& v, size_t) { bytes += 2 + v.size(); }
  void blob(Bytes& v, size_t) { bytes += 4 + v.size(); }
  void hash(Hash&) { bytes += 32; }
  size_t count(size_t n, size_t, const char*) {
    bytes += 2;
    return n;
  }
  size_t bytes = 0;
};

}  // namespace inkwire::protocol
