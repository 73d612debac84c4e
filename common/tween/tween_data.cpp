#include "common/tween/tween_data.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "common/error.hpp"

// Layout (little-endian; the full field-by-field description is in protocol/SPEC.md, "Tween
// data"):
//   "IKTW", u8 version (1), u8 reserved (0), u16 width, u16 height, u16 samples, u16 cells,
//   per sample its view direction as 3 x i16 (component x 32767)
//   per cell: u8 arity (2|3), u16 sample index x arity, u16 point count, and when points > 0:
//     six streams of integers, each as (zigzag varint minimum, u8 bit width), then the
//     streams' values minus their minimum, bit-packed LSB first, stream after stream, padded
//     to a whole byte. The streams are x0, y0 (position in the first sample, 1/16 px) and two
//     predicted differences: a pair stores q2 - q0 and q1 - (q0 + q2) / 2 (the halfway point's
//     bend off the straight path, nearly 0), a triangle q1 - q0 and q2 - q0.
// Bit widths adapt to each cell's spread, which is what brings 65 points under 500 bytes.

namespace inkwire {
namespace {

constexpr uint8_t kVersion = 1;
constexpr char kMagic[4] = {'I', 'K', 'T', 'W'};
constexpr int kStreams = 6;
constexpr int kMaxBits = 17;  // a difference of two 16-bit values

int quantise(float pixels, int side) {
  const float q = std::round(pixels * float(1 << kTweenFractionBits));
  if (!std::isfinite(q)) return 0;
  return int(std::clamp(q, 0.0f, float(side << kTweenFractionBits)));
}
float dequantise(int q) { return float(q) / float(1 << kTweenFractionBits); }
int quantise_direction(float v) { return int(std::round(std::clamp(std::isfinite(v) ? v : 0.0f, -1.0f, 1.0f) * 32767.0f)); }
float dequantise_direction(int q) { return std::clamp(float(q) / 32767.0f, -1.0f, 1.0f); }

class Writer {
 public:
  void u8(uint32_t v) { bytes.push_back(uint8_t(v)); }
  void u16(uint32_t v) {
    u8(v & 0xff);
    u8(v >> 8);
  }
  void varint(int32_t v) {
    uint32_t z = (uint32_t(v) << 1) ^ uint32_t(v >> 31);
    while (z >= 0x80) {
      u8((z & 0x7f) | 0x80);
      z >>= 7;
    }
    u8(z);
  }
  void bits(uint32_t value, int count) {
    for (int i = 0; i < count; ++i) {
      if (bit_ == 0) bytes.push_back(0);
      bytes.back() |= uint8_t(((value >> i) & 1u) << bit_);
      bit_ = (bit_ + 1) % 8;
    }
  }
  void end_bits() { bit_ = 0; }
  std::vector<uint8_t> bytes;

 private:
  int bit_ = 0;
};

class Reader {
 public:
  explicit Reader(std::span<const uint8_t> b) : b_(b) {}
  size_t remaining() const { return b_.size() - pos_; }
  void need(size_t n, const char* what) const {
    if (remaining() < n) throw Error(std::string("tween data: truncated in ") + what);
  }
  uint32_t u8(const char* what) {
    need(1, what);
    return b_[pos_++];
  }
  uint32_t u16(const char* what) {
    need(2, what);
    const uint32_t v = b_[pos_] | (uint32_t(b_[pos_ + 1]) << 8);
    pos_ += 2;
    return v;
  }
  int32_t varint(const char* what) {
    uint32_t z = 0;
    for (int shift = 0;; shift += 7) {
      if (shift > 28) throw Error(std::string("tween data: over-long number in ") + what);
      const uint32_t byte = u8(what);
      z |= (byte & 0x7f) << shift;
      if (!(byte & 0x80)) break;
    }
    return int32_t(z >> 1) ^ -int32_t(z & 1);
  }
  uint32_t bits(int count) {  // callers check need() for the whole block first
    uint32_t v = 0;
    for (int i = 0; i < count; ++i) {
      v |= uint32_t((b_[pos_] >> bit_) & 1u) << i;
      if (++bit_ == 8) {
        bit_ = 0;
        ++pos_;
      }
    }
    return v;
  }
  void end_bits() {
    if (bit_ != 0) ++pos_;
    bit_ = 0;
  }

 private:
  std::span<const uint8_t> b_;
  size_t pos_ = 0;
  int bit_ = 0;
};

int bits_for(uint32_t spread) {
  int n = 0;
  while (n < 32 && (spread >> n) != 0) ++n;
  return n;
}

void check_limits(const TweenData& d) {
  if (d.width < 1 || d.height < 1 || d.width > kMaxTweenImageSide || d.height > kMaxTweenImageSide)
    throw Error("tween data: image size " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                " is outside 1.." + std::to_string(kMaxTweenImageSide));
  if (d.sample_count() < 2 || d.sample_count() > kMaxTweenSamples)
    throw Error("tween data: " + std::to_string(d.sample_count()) + " samples (2.." + std::to_string(kMaxTweenSamples) + " allowed)");
  if (d.cells.size() > size_t(kMaxTweenCells)) throw Error("tween data: too many cells (" + std::to_string(d.cells.size()) + ")");
  for (const TweenCell& c : d.cells) {
    if (c.samples.size() != 2 && c.samples.size() != 3)
      throw Error("tween data: a cell has " + std::to_string(c.samples.size()) + " samples (2 or 3 allowed)");
    for (size_t i = 0; i < c.samples.size(); ++i) {
      if (c.samples[i] >= d.sample_count())
        throw Error("tween data: sample index " + std::to_string(c.samples[i]) + " out of range (" +
                    std::to_string(d.sample_count()) + " samples)");
      for (size_t j = 0; j < i; ++j)
        if (c.samples[i] == c.samples[j]) throw Error("tween data: a cell names sample " + std::to_string(c.samples[i]) + " twice");
    }
    if (c.points.size() > size_t(kMaxTweenPointsPerCell))
      throw Error("tween data: a cell has " + std::to_string(c.points.size()) + " points (at most " +
                  std::to_string(kMaxTweenPointsPerCell) + ")");
  }
}

struct Quantised {
  int x[3], y[3];
};

// The six stream values of a point, and back.
std::array<int32_t, kStreams> predict(const Quantised& q, bool pair) {
  if (pair) return {q.x[0], q.y[0], q.x[2] - q.x[0], q.y[2] - q.y[0], q.x[1] - (q.x[0] + q.x[2]) / 2, q.y[1] - (q.y[0] + q.y[2]) / 2};
  return {q.x[0], q.y[0], q.x[1] - q.x[0], q.y[1] - q.y[0], q.x[2] - q.x[0], q.y[2] - q.y[0]};
}
Quantised unpredict(const std::array<int32_t, kStreams>& s, bool pair) {
  Quantised q{};
  q.x[0] = s[0];
  q.y[0] = s[1];
  if (pair) {
    q.x[2] = s[0] + s[2];
    q.y[2] = s[1] + s[3];
    q.x[1] = s[4] + (q.x[0] + q.x[2]) / 2;
    q.y[1] = s[5] + (q.y[0] + q.y[2]) / 2;
  } else {
    q.x[1] = s[0] + s[2];
    q.y[1] = s[1] + s[3];
    q.x[2] = s[0] + s[4];
    q.y[2] = s[1] + s[5];
  }
  return q;
}

void write_cell(Writer& w, const TweenCell& c, int image_width, int image_height) {
  w.u8(uint32_t(c.samples.size()));
  for (uint16_t s : c.samples) w.u16(s);
  w.u16(uint32_t(c.points.size()));
  if (c.points.empty()) return;
  std::vector<std::array<int32_t, kStreams>> values;
  for (const ControlPoint& p : c.points) {
    Quantised q{};
    for (int k = 0; k < 3; ++k) {
      q.x[k] = quantise(p[k].x, image_width);
      q.y[k] = quantise(p[k].y, image_height);
    }
    values.push_back(predict(q, c.is_pair()));
  }
  std::array<int32_t, kStreams> lo{}, width{};
  for (int s = 0; s < kStreams; ++s) {
    int32_t mn = values[0][s], mx = values[0][s];
    for (const auto& v : values) {
      mn = std::min(mn, v[s]);
      mx = std::max(mx, v[s]);
    }
    lo[s] = mn;
    width[s] = bits_for(uint32_t(mx - mn));
    w.varint(mn);
    w.u8(uint32_t(width[s]));
  }
  for (int s = 0; s < kStreams; ++s)
    for (const auto& v : values) w.bits(uint32_t(v[s] - lo[s]), width[s]);
  w.end_bits();
}

TweenCell read_cell(Reader& r, uint32_t ci, int image_width, int image_height) {
  const int max_q[2] = {image_width << kTweenFractionBits, image_height << kTweenFractionBits};
  TweenCell c;
  const uint32_t arity = r.u8("a cell header");
  if (arity != 2 && arity != 3) throw Error("tween data: cell " + std::to_string(ci) + " has arity " + std::to_string(arity) + " (2 or 3)");
  for (uint32_t k = 0; k < arity; ++k) c.samples.push_back(uint16_t(r.u16("a cell header")));
  const uint32_t count = r.u16("a cell header");
  if (count > uint32_t(kMaxTweenPointsPerCell))
    throw Error("tween data: cell " + std::to_string(ci) + " has " + std::to_string(count) + " points (at most " +
                std::to_string(kMaxTweenPointsPerCell) + ")");
  if (count == 0) return c;
  std::array<int32_t, kStreams> lo{}, width{};
  size_t total_bits = 0;
  for (int s = 0; s < kStreams; ++s) {
    lo[s] = r.varint("a stream header");
    width[s] = int32_t(r.u8("a stream header"));
    if (lo[s] < -65535 || lo[s] > 65535 || width[s] > kMaxBits)
      throw Error("tween data: cell " + std::to_string(ci) + " has a malformed stream header");
    total_bits += size_t(width[s]) * count;
  }
  r.need((total_bits + 7) / 8, "point data");
  std::vector<std::array<int32_t, kStreams>> values(count);
  for (int s = 0; s < kStreams; ++s)
    for (auto& v : values) v[s] = lo[s] + int32_t(r.bits(width[s]));
  r.end_bits();
  c.points.reserve(count);
  for (const auto& v : values) {
    const Quantised q = unpredict(v, arity == 2);
    ControlPoint p;
    for (int k = 0; k < 3; ++k) {
      if (q.x[k] < 0 || q.y[k] < 0 || q.x[k] > max_q[0] || q.y[k] > max_q[1])
        throw Error("tween data: cell " + std::to_string(ci) + " has a point outside the image");
      p[k] = {dequantise(q.x[k]), dequantise(q.y[k])};
    }
    c.points.push_back(p);
  }
  return c;
}

}  // namespace

glm::vec3 path_weights(float t) {
  const float u = 1.0f - t;
  return {u * u - t * u, 4.0f * t * u, t * t - t * u};
}

glm::vec2 path_position(const ControlPoint& p, float t) {
  const glm::vec3 w = path_weights(t);
  return w.x * p[0] + w.y * p[1] + w.z * p[2];
}

TweenData quantised(const TweenData& data) {
  TweenData out = data;
  for (glm::vec3& v : out.directions)
    for (int k = 0; k < 3; ++k) v[k] = dequantise_direction(quantise_direction(v[k]));
  for (TweenCell& c : out.cells)
    for (ControlPoint& p : c.points)
      for (glm::vec2& v : p) v = {dequantise(quantise(v.x, data.width)), dequantise(quantise(v.y, data.height))};
  return out;
}

std::vector<uint8_t> encode_tween(const TweenData& data) {
  check_limits(data);
  Writer w;
  for (char c : kMagic) w.u8(uint8_t(c));
  w.u8(kVersion);
  w.u8(0);
  w.u16(data.width);
  w.u16(data.height);
  w.u16(uint32_t(data.sample_count()));
  w.u16(uint32_t(data.cells.size()));
  for (const glm::vec3& v : data.directions)
    for (int k = 0; k < 3; ++k) w.u16(uint16_t(quantise_direction(v[k])));
  for (const TweenCell& c : data.cells) write_cell(w, c, data.width, data.height);
  if (w.bytes.size() > kMaxTweenBytes) throw Error("tween data: encoding is " + std::to_string(w.bytes.size()) + " bytes, over the limit");
  return std::move(w.bytes);
}

std::vector<uint8_t> encode_tween_cell(const TweenCell& cell, int width, int height, int samples) {
  TweenData header;
  header.width = width;
  header.height = height;
  header.directions.assign(size_t(std::max(samples, 0)), glm::vec3(0, 0, 1));
  header.cells = {cell};
  check_limits(header);
  Writer w;
  write_cell(w, cell, width, height);
  return std::move(w.bytes);
}

TweenCell decode_tween_cell(std::span<const uint8_t> bytes, int width, int height, int samples) {
  if (bytes.size() > kMaxTweenCellBytes) throw Error("tween data: a cell of " + std::to_string(bytes.size()) + " bytes is over the limit");
  Reader r(bytes);
  TweenData d;
  d.width = width;
  d.height = height;
  d.directions.assign(size_t(std::max(samples, 0)), glm::vec3(0, 0, 1));
  d.cells.push_back(read_cell(r, 0, width, height));
  if (r.remaining() != 0) throw Error("tween data: " + std::to_string(r.remaining()) + " bytes after the cell");
  check_limits(d);
  return std::move(d.cells[0]);
}

TweenData decode_tween(std::span<const uint8_t> bytes) {
  if (bytes.size() > kMaxTweenBytes) throw Error("tween data: " + std::to_string(bytes.size()) + " bytes is over the limit");
  Reader r(bytes);
  for (char c : kMagic)
    if (r.u8("the header") != uint8_t(c)) throw Error("tween data: not tween data (bad magic)");
  const uint32_t version = r.u8("the header");
  if (version != kVersion)
    throw Error("tween data: version " + std::to_string(version) + " is not supported (this build reads " + std::to_string(kVersion) + ")");
  if (r.u8("the header") != 0) throw Error("tween data: reserved header byte is not 0");
  TweenData d;
  d.width = int(r.u16("the header"));
  d.height = int(r.u16("the header"));
  const uint32_t samples = r.u16("the header");
  const uint32_t cells = r.u16("the header");
  if (samples < 2 || samples > uint32_t(kMaxTweenSamples))
    throw Error("tween data: " + std::to_string(samples) + " samples (2.." + std::to_string(kMaxTweenSamples) + " allowed)");
  r.need(size_t(samples) * 6, "the sample directions");
  for (uint32_t i = 0; i < samples; ++i) {
    glm::vec3 v;
    for (int k = 0; k < 3; ++k) v[k] = dequantise_direction(int16_t(r.u16("the sample directions")));
    if (glm::length(v) < 0.5f) throw Error("tween data: sample " + std::to_string(i) + " has no view direction");
    d.directions.push_back(v);
  }
  check_limits(d);
  if (cells > uint32_t(kMaxTweenCells)) throw Error("tween data: too many cells (" + std::to_string(cells) + ")");
  // Every cell takes at least 5 bytes: refuse a count the input cannot hold before reserving.
  if (size_t(cells) * 5 > r.remaining()) throw Error("tween data: truncated (" + std::to_string(cells) + " cells announced)");
  d.cells.reserve(cells);
  for (uint32_t ci = 0; ci < cells; ++ci) d.cells.push_back(read_cell(r, ci, d.width, d.height));
  if (r.remaining() != 0) throw Error("tween data: " + std::to_string(r.remaining()) + " bytes after the last cell");
  check_limits(d);
  return d;
}

}  // namespace inkwire
