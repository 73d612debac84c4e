#pragma once
// A call's voice as Opus (SPEC F9): mono, 48 kHz in and out, packets of `frame_ms` (20, 40 or
// 60) at `bitrate` bits a second (6000..12000 for calls). One encoder per publisher, one decoder
// per member heard: Opus keeps state from packet to packet.
#include <cstdint>
#include <span>
#include <vector>

struct OpusEncoder;
struct OpusDecoder;

namespace inkwire {

class VoiceEncoder {
 public:
  // Throws inkwire::Error for a frame length or bit rate Opus does not take.
  VoiceEncoder(int frame_ms = 40, int bitrate = 8000);
  ~VoiceEncoder();
  VoiceEncoder(const VoiceEncoder&) = delete;
  VoiceEncoder& operator=(const VoiceEncoder&) = delete;
  int frame_samples() const { return frame_samples_; }
  // One packet of exactly frame_samples() samples.
  std::vector<uint8_t> encode(std::span<const float> frame);

 private:
  OpusEncoder* encoder_ = nullptr;
  int frame_samples_ = 0;
};

class VoiceDecoder {
 public:
  VoiceDecoder();
  ~VoiceDecoder();
  VoiceDecoder(const VoiceDecoder&) = delete;
  VoiceDecoder& operator=(const VoiceDecoder&) = delete;
  // The packet's samples, or nothing when it does not decode; `missing` samples (a lost packet
  // of that length) are concealed from what came before.
  std::vector<float> decode(std::span<const uint8_t> packet);
  std::vector<float> conceal(int samples);

 private:
  OpusDecoder* decoder_ = nullptr;
};

}  // namespace inkwire
