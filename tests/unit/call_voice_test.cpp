// What the server reads from relayed voice (server/call/voice_analysis.hpp, SPEC F10): Opus
// packets made here with libopus from synthetic sounds, whose level and mouth shape are known:
// silence is a closed mouth, a low hum with few zero crossings round, hiss wide, a voiced
// vowel-like buzz open. Bytes that are not mono Opus are refused with the reason.
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>
#include <opus.h>

#include "server/call/voice_analysis.hpp"

using namespace inkwire;
using namespace inkwire::server;

namespace {

constexpr int kRate = 48000, kFrame = 960;  // 20 ms

// One 20 ms Opus packet (mono, 12 kbit/s, as a call sends) of `make(t)` in -1..1, after a few
// packets of the same sound so the encoder has settled.
std::vector<uint8_t> packet_of(const std::function<float(int)>& make) {
  int error = 0;
  OpusEncoder* encoder = opus_encoder_create(kRate, 1, OPUS_APPLICATION_VOIP, &error);
  opus_encoder_ctl(encoder, OPUS_SET_BITRATE(12000));
  std::vector<float> pcm(kFrame);
  std::vector<uint8_t> out(400);
  int n = 0;
  for (int frame = 0; frame < 6; ++frame) {
    for (int i = 0; i < kFrame; ++i) pcm[size_t(i)] = make(frame * kFrame + i);
    n = opus_encode_float(encoder, pcm.data(), kFrame, out.data(), opus_int32(out.size()));
  }
  opus_encoder_destroy(encoder);
  out.resize(size_t(std::max(n, 0)));
  return out;
}

const float kPi = 3.14159265f;

}  // namespace

TEST(CallVoiceTest, LevelsAndMouthShapesOfKnownSounds) {
  // White noise in -1..1 by sample index (a hash, so a sound is a plain function of time).
  const auto noise = [](int t) {
    uint32_t x = uint32_t(t) * 2654435761u;
    x ^= x >> 15, x *= 2246822519u, x ^= x >> 13;
    return float(int32_t(x)) / 2147483648.0f;
  };
  struct Case {
    const char* what;
    std::function<float(int)> sound;
    Expression mouth;
  };
  const Case cases[] = {
      {"silence", [](int) { return 0.0f; }, Expression::VisemeClosed},
      {"a 200 Hz hum", [](int t) { return 0.3f * std::sin(2 * kPi * 200 * float(t) / kRate); }, Expression::VisemeRound},
      // White noise differentiated: mostly high frequencies, as in "s" and "ee".
      {"hiss", [&](int t) { return 0.3f * (noise(t) - noise(t - 1)); }, Expression::VisemeWide},
      {"a buzz at 150 Hz with its harmonics to 1.5 kHz", [](int t) {
         float s = 0;
         for (int h = 1; h <= 10; ++h) s += std::sin(2 * kPi * 150 * float(h) * float(t) / kRate) / float(h) * (h >= 4 && h <= 6 ? 3.0f : 1.0f);
         return 0.12f * s;
       }, Expression::VisemeOpen},
  };
  for (const Case& c : cases) {
    VoiceAnalysis voice;
    const auto reading = voice.read(packet_of(c.sound));
    ASSERT_TRUE(reading) << c.what;
    EXPECT_EQ(reading->samples, 320) << c.what;
    EXPECT_EQ(reading->mouth.expression, c.mouth) << c.what << ": got " << name_of(reading->mouth.expression) << " at " << reading->level_db << " dB";
    if (c.mouth == Expression::VisemeClosed) EXPECT_LT(reading->level_db, VoiceAnalysis::kSilenceDb) << c.what;
    else EXPECT_GT(reading->level_db, VoiceAnalysis::kSilenceDb + 5) << c.what;  // heard as sound, not silence
  }
}

TEST(CallVoiceTest, BytesThatAreNotMonoOpusAreRefusedWithTheReason) {
  VoiceAnalysis voice;
  std::string reason;
  EXPECT_FALSE(voice.read(std::vector<uint8_t>{}, &reason));
  EXPECT_EQ(reason, "empty voice frame");
  // TOC byte 0x04: config 0 with the stereo bit set.
  EXPECT_FALSE(voice.read(std::vector<uint8_t>{0x04, 1, 2, 3}, &reason));
  EXPECT_EQ(reason, "voice frame is not mono Opus");
  // Code 3 (a frame count byte follows) with a count of 0: no Opus packet.
  EXPECT_FALSE(voice.read(std::vector<uint8_t>{0x03, 0x00}, &reason));
  EXPECT_FALSE(reason.empty());
}

// Found by fuzz_voice (2026-11-25): the 6-byte packet below decodes past full scale, and its
// level read as more than 0 dB. Levels are of the clipped sound now.
TEST(CallVoiceTest, APacketDecodingPastFullScaleReadsAtMostFullScale) {
  VoiceAnalysis voice;
  const auto reading = voice.read(std::vector<uint8_t>{0xd0, 0x2e, 0x2f, 0x29, 0xd0, 0x74});
  ASSERT_TRUE(reading);
  EXPECT_LE(reading->level_db, 0.0f);
  for (float s : voice.samples()) EXPECT_LE(std::abs(s), 1.0f);
}
