// What a call member hears (client/call/call_audio.hpp, SPEC F9): a member's tone, sent as 20 ms
// Opus packets whose first came slowly and whose later ones come quicker, then one late, mixed
// on the listener's clock. The offset catches up with the quick packets by skipping the start of
// one, and the sound runs on without a gap or a doubled stretch; the late packet raises the
// delay once, leaving one pause.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "client/call/audio_file.hpp"
#include "client/call/call_audio.hpp"
#include "client/call/voice_codec.hpp"

using namespace inkwire;

namespace {

constexpr int kFrameMs = 20, kFrame = kCallRate * kFrameMs / 1000;

}  // namespace

TEST(CallAudioTest, TheOffsetCatchesUpWithQuickPacketsWithoutAGapOrAnOverlap) {
  VoiceEncoder encoder(kFrameMs, 12000);
  const auto start = CallAudio::Clock::now();
  const auto at = [&](double ms) { return start + std::chrono::microseconds(std::llround(ms * 1000)); };
  CallAudio audio(start);
  std::vector<float> heard;
  const auto hear_until = [&](double ms) {
    const std::vector<float> part = audio.take(at(ms));
    heard.insert(heard.end(), part.begin(), part.end());
  };
  constexpr int kPackets = 60;
  std::vector<float> tone(kFrame);
  for (int k = 0; k < kPackets; ++k) {
    for (int i = 0; i < kFrame; ++i) tone[size_t(i)] = 0.3f * std::sin(2.0f * 3.14159265f * 300.0f * float(k * kFrame + i) / kCallRate);
    const std::vector<uint8_t> opus = encoder.encode(tone);
    // Packet k leaves at 20k ms: the first arrives 30 ms later, the others 12 ms later, the 40th 150 ms later.
    const double arrives = kFrameMs * k + (k == 0 ? 30.0 : k == 40 ? 150.0 : 12.0);
    hear_until(arrives);
    audio.add(protocol::VoiceFrame{.member = 3, .time_ms = uint32_t(kFrameMs * k), .opus = opus}, at(arrives));
  }
  hear_until(kFrameMs * kPackets + 400);

  EXPECT_EQ(audio.played(), uint64_t(kPackets));
  EXPECT_EQ(audio.skipped(), 0u) << "18 ms sooner is less than a packet: its start is skipped, not all of it";
  EXPECT_EQ(audio.late(), 0u);
  // The first packet plays 30 + 80 ms after it was sent; after the catch-up 12 + 80, and after the
  // late packet (150 ms on its way, 58 past its moment) 12 + 80 + 58 + the margin.
  const auto local = audio.local_time(3, 1000);
  ASSERT_TRUE(local);
  const double local_ms = std::chrono::duration<double, std::milli>(*local - start).count();
  EXPECT_NEAR(local_ms, 1000 + 12 + kStartDelayMs + 58 + kDelayMarginMs, 0.5);

  // Between the first sound and the last, the tone (peak 0.3) runs on: a stretch of 1 ms or more
  // near zero is a gap, a peak past 0.4 an overlap. The late packet raised the delay by 78 ms: one
  // pause of that length, nothing else.
  const auto sounding = [](float x) { return std::abs(x) > 0.01f; };
  const auto begin = std::find_if(heard.begin(), heard.end(), sounding);
  const auto end = std::find_if(heard.rbegin(), heard.rend(), sounding).base();
  ASSERT_LT(begin, end);
  std::vector<double> pauses_ms;
  float peak = 0;
  for (auto at = begin; at < end;) {
    const auto quiet_end = std::find_if(at, end, sounding);
    if (quiet_end - at >= kCallRate / 1000) pauses_ms.push_back(double(quiet_end - at) * 1000.0 / kCallRate);
    at = std::find_if_not(quiet_end, end, sounding);
    for (auto i = quiet_end; i < at; ++i) peak = std::max(peak, std::abs(*i));
  }
  EXPECT_LE(peak, 0.4f) << "some of the tone was mixed twice";
  ASSERT_EQ(pauses_ms.size(), 1u) << "a gap where the offset caught up, or no pause where the delay grew";
  EXPECT_NEAR(pauses_ms[0], 58 + kDelayMarginMs, 2.0);
}
