#pragma once
// What the server reads from the voice it relays (SPEC F10, F12): each Opus packet is decoded
// (at 16 kHz, enough for speech) to check that it is Opus, measure its level (who is speaking,
// who is among the loudest) and read a mouth shape from it: the study's visemes closed, open,
// wide and round, which drive a member's mouth when its camera is off or its face is lost.
// The rule: quiet is closed; energy mostly above 2 kHz (the "ee" and "s" of spread lips) is
// wide; energy mostly below 700 Hz with few zero crossings (the "oo" and "o" of rounded lips)
// is round; any other voiced sound is open. Not thread-safe: one per member.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/face/expression.hpp"

struct OpusDecoder;

namespace inkwire::server {

struct VoiceReading {
  int samples = 0;         // at 16 kHz: 320 for a 20 ms packet
  float level_db = -100;   // RMS level, dB below full scale
  ExpressionState mouth;   // a viseme and its intensity
};

class VoiceAnalysis {
 public:
  static constexpr int kRate = 16000;
  static constexpr float kSilenceDb = -45;  // quieter than this is silence (closed mouth, not speaking)

  VoiceAnalysis();
  ~VoiceAnalysis();
  VoiceAnalysis(const VoiceAnalysis&) = delete;
  VoiceAnalysis& operator=(const VoiceAnalysis&) = delete;

  // One packet's reading, or the reason it is no Opus this decoder takes (mono, 2.5-60 ms).
  // The decoded samples of the latest packet stay in samples() until the next.
  std::optional<VoiceReading> read(std::span<const uint8_t> packet, std::string* reason = nullptr);
  std::span<const float> samples() const { return {pcm_.data(), size_t(last_)}; }

 private:
  OpusDecoder* decoder_ = nullptr;
  std::vector<float> pcm_;
  int last_ = 0;
};

// The mouth shape of 16 kHz samples at `level_db` (the rule above), for tests and the reader.
ExpressionState mouth_of(std::span<const float> samples, float level_db);

}  // namespace inkwire::server
