#include "client/call/audio_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include <samplerate.h>

#include "common/error.hpp"

namespace inkwire {
namespace {

uint32_t u32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }
uint16_t u16(const uint8_t* p) { return uint16_t(p[0] | p[1] << 8); }
constexpr size_t kMaxWavBytes = size_t(1) << 30;

}  // namespace

std::vector<float> read_wav_mono(const std::filesystem::path& file, int rate) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot read sound file '" + file.string() + "'");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string what = "'" + file.string() + "'";
  if (bytes.size() < 12 || std::memcmp(bytes.data(), "RIFF", 4) != 0 || std::memcmp(bytes.data() + 8, "WAVE", 4) != 0 || bytes.size() > kMaxWavBytes)
    throw Error(what + " is not a WAV file");
  int channels = 0, source_rate = 0, bits = 0, format = 0;
  const uint8_t* data = nullptr;
  size_t data_bytes = 0;
  for (size_t at = 12; at + 8 <= bytes.size();) {
    const uint32_t size = u32(&bytes[at + 4]);
    const size_t body = at + 8, available = std::min<size_t>(size, bytes.size() - body);
    if (!std::memcmp(&bytes[at], "fmt ", 4) && available >= 16) {
      format = u16(&bytes[body]);
      channels = u16(&bytes[body + 2]);
      source_rate = int(u32(&bytes[body + 4]));
      bits = u16(&bytes[body + 14]);
      if (format == 0xfffe && available >= 26) format = u16(&bytes[body + 24]);  // WAVE_FORMAT_EXTENSIBLE: the sub-format
    } else if (!std::memcmp(&bytes[at], "data", 4)) {
      data = &bytes[body];
      data_bytes = available;  // espeak-ng streams write a size of 0x7fffffff: what is there counts
    }
    at = body + size + (size & 1);
    if (at < body) break;  // overflow
  }
  if (!data) throw Error(what + " has no sound data");
  if (channels < 1 || channels > 8 || source_rate < 4000 || source_rate > 192000) throw Error(what + ": unsupported channels or rate");
  const bool pcm16 = format == 1 && bits == 16, float32 = format == 3 && bits == 32;
  if (!pcm16 && !float32) throw Error(what + ": only 16-bit PCM and 32-bit float WAV are read");
  const size_t frame_bytes = size_t(channels) * size_t(bits / 8), frames = data_bytes / frame_bytes;
  std::vector<float> mono(frames);
  for (size_t f = 0; f < frames; ++f) {
    float sum = 0;
    for (int c = 0; c < channels; ++c) {
      const uint8_t* p = data + f * frame_bytes + size_t(c) * size_t(bits / 8);
      if (pcm16) sum += float(int16_t(u16(p))) / 32768.0f;
      else {
        float v;
        std::memcpy(&v, p, 4);
        sum += std::isfinite(v) ? v : 0.0f;
      }
    }
    mono[f] = sum / float(channels);
  }
  if (source_rate == rate || mono.empty()) return mono;
  std::vector<float> out(size_t(double(mono.size()) * rate / source_rate) + 16);
  SRC_DATA src{};
  src.data_in = mono.data();
  src.input_frames = long(mono.size());
  src.data_out = out.data();
  src.output_frames = long(out.size());
  src.src_ratio = double(rate) / source_rate;
  if (const int error = src_simple(&src, SRC_SINC_FASTEST, 1)) throw Error(what + ": resampling failed: " + src_strerror(error));
  out.resize(size_t(src.output_frames_gen));
  return out;
}

void write_wav_mono(const std::filesystem::path& file, const std::vector<float>& samples, int rate) {
  std::vector<uint8_t> out(44 + samples.size() * 2);
  const auto put32 = [&](size_t at, uint32_t v) { for (int i = 0; i < 4; ++i) out[at + size_t(i)] = uint8_t(v >> (8 * i)); };
  const auto put16 = [&](size_t at, uint16_t v) { out[at] = uint8_t(v), out[at + 1] = uint8_t(v >> 8); };
  std::copy_n("RIFF", 4, out.begin());
  put32(4, uint32_t(out.size() - 8));
  std::copy_n("WAVEfmt ", 8, out.begin() + 8);
  put32(16, 16), put16(20, 1), put16(22, 1), put32(24, uint32_t(rate)), put32(28, uint32_t(rate * 2)), put16(32, 2), put16(34, 16);
  std::copy_n("data", 4, out.begin() + 36);
  put32(40, uint32_t(samples.size() * 2));
  for (size_t i = 0; i < samples.size(); ++i) put16(44 + 2 * i, uint16_t(int16_t(std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32767.0f))));
  std::ofstream f(file, std::ios::binary);
  f.write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
  if (!f) throw Error("cannot write '" + file.string() + "'");
}

}  // namespace inkwire
