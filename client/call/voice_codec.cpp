#include "client/call/voice_codec.hpp"

#include <opus.h>

#include "client/call/audio_file.hpp"
#include "common/error.hpp"

namespace inkwire {

VoiceEncoder::VoiceEncoder(int frame_ms, int bitrate) : frame_samples_(kCallRate * frame_ms / 1000) {
  if (frame_ms != 20 && frame_ms != 40 && frame_ms != 60) throw Error("voice frames are 20, 40 or 60 ms");
  if (bitrate < 6000 || bitrate > 64000) throw Error("voice bit rate must be 6000..64000");
  int error = 0;
  encoder_ = opus_encoder_create(kCallRate, 1, OPUS_APPLICATION_VOIP, &error);
  if (error != OPUS_OK) throw Error(std::string("opus encoder: ") + opus_strerror(error));
  opus_encoder_ctl(encoder_, OPUS_SET_BITRATE(bitrate));
  opus_encoder_ctl(encoder_, OPUS_SET_SIGNAL(OPUS_SIGNAL_VOICE));
  opus_encoder_ctl(encoder_, OPUS_SET_DTX(0));
}

VoiceEncoder::~VoiceEncoder() { opus_encoder_destroy(encoder_); }

std::vector<uint8_t> VoiceEncoder::encode(std::span<const float> frame) {
  if (int(frame.size()) != frame_samples_) throw Error("voice frame of the wrong length");
  std::vector<uint8_t> out(400);
  const int n = opus_encode_float(encoder_, frame.data(), frame_samples_, out.data(), opus_int32(out.size()));
  if (n < 0) throw Error(std::string("opus encode: ") + opus_strerror(n));
  out.resize(size_t(n));
  return out;
}

VoiceDecoder::VoiceDecoder() {
  int error = 0;
  decoder_ = opus_decoder_create(kCallRate, 1, &error);
  if (error != OPUS_OK) throw Error(std::string("opus decoder: ") + opus_strerror(error));
}

VoiceDecoder::~VoiceDecoder() { opus_decoder_destroy(decoder_); }

std::vector<float> VoiceDecoder::decode(std::span<const uint8_t> packet) {
  std::vector<float> out(size_t(kCallRate * 120 / 1000));
  const int n = opus_decode_float(decoder_, packet.data(), opus_int32(packet.size()), out.data(), int(out.size()), 0);
  if (n < 0) return {};
  out.resize(size_t(n));
  return out;
}

std::vector<float> VoiceDecoder::conceal(int samples) {
  std::vector<float> out(size_t(std::max(samples, 0)));
  if (samples > 0 && opus_decode_float(decoder_, nullptr, 0, out.data(), samples, 0) < 0) std::fill(out.begin(), out.end(), 0.0f);
  return out;
}

}  // namespace inkwire
