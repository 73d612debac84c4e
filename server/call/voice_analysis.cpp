#include "server/call/voice_analysis.hpp"

#include <algorithm>
#include <cmath>

#include <opus.h>

#include "common/error.hpp"

namespace inkwire::server {
namespace {

constexpr int kMaxSamples = VoiceAnalysis::kRate * 60 / 1000;  // the longest Opus packet, 60 ms
constexpr float kLoudDb = -12;                                 // as loud as speech gets: full intensity

// One-pole low-pass coefficient for a cut-off of `hz` at 16 kHz.
float low_pass(float hz) { return 1.0f - std::exp(-2.0f * 3.14159265f * hz / float(VoiceAnalysis::kRate)); }

}  // namespace

ExpressionState mouth_of(std::span<const float> samples, float level_db) {
  if (samples.empty() || level_db < VoiceAnalysis::kSilenceDb) return {Expression::VisemeClosed, 255};
  const float a_low = low_pass(700), a_mid = low_pass(2000);
  float low = 0, mid = 0, e_low = 0, e_high = 0, e_all = 0;
  int crossings = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const float x = samples[i];
    low += a_low * (x - low);
    mid += a_mid * (x - mid);
    const float high = x - mid;  // above about 2 kHz
    e_low += low * low, e_high += high * high, e_all += x * x;
    if (i > 0 && (samples[i - 1] < 0) != (x < 0)) ++crossings;
  }
  const float low_share = e_low / std::max(e_all, 1e-12f), high_share = e_high / std::max(e_all, 1e-12f);
  const float crossing_rate = float(crossings) / float(samples.size());  // per sample
  const auto intensity = uint8_t(std::clamp((level_db - VoiceAnalysis::kSilenceDb) / (kLoudDb - VoiceAnalysis::kSilenceDb), 0.2f, 1.0f) * 255.0f);
  if (high_share > 0.35f) return {Expression::VisemeWide, intensity};
  if (low_share > 0.75f && crossing_rate < 0.06f) return {Expression::VisemeRound, intensity};
  return {Expression::VisemeOpen, intensity};
}

VoiceAnalysis::VoiceAnalysis() : pcm_(size_t(kMaxSamples)) {
  int error = 0;
  decoder_ = opus_decoder_create(kRate, 1, &error);
  if (error != OPUS_OK || !decoder_) throw Error(std::string("opus decoder: ") + opus_strerror(error));
}

VoiceAnalysis::~VoiceAnalysis() { opus_decoder_destroy(decoder_); }

std::optional<VoiceReading> VoiceAnalysis::read(std::span<const uint8_t> packet, std::string* reason) {
  const auto refuse = [&](std::string why) -> std::optional<VoiceReading> {
    if (reason) *reason = std::move(why);
    return std::nullopt;
  };
  if (packet.empty()) return refuse("empty voice frame");
  if (opus_packet_get_nb_channels(packet.data()) != 1) return refuse("voice frame is not mono Opus");
  const int samples = opus_packet_get_nb_samples(packet.data(), opus_int32(packet.size()), kRate);
  if (samples <= 0) return refuse("voice frame is not Opus");
  if (samples > kMaxSamples) return refuse("voice frame longer than 60 ms");
  const int decoded = opus_decode_float(decoder_, packet.data(), opus_int32(packet.size()), pcm_.data(), kMaxSamples, 0);
  if (decoded <= 0) return refuse(std::string("voice frame does not decode: ") + opus_strerror(decoded));
  last_ = decoded;
  // Opus may decode past full scale (a hostile packet far past it): the level is of what a
  // sound card would play, clipped, so nobody is "louder than loud" (found by fuzz_voice).
  double sum = 0;
  for (int i = 0; i < decoded; ++i) {
    float& s = pcm_[size_t(i)];
    s = std::isfinite(s) ? std::clamp(s, -1.0f, 1.0f) : 0.0f;
    sum += double(s) * s;
  }
  const float rms = float(std::sqrt(sum / decoded));
  VoiceReading reading{.samples = decoded, .level_db = 20.0f * std::log10(std::max(rms, 1e-5f)), .mouth = {}};
  reading.mouth = mouth_of(this->samples(), reading.level_db);
  return reading;
}

}  // namespace inkwire::server
