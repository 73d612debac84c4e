#include "client/call/call_audio.hpp"

#include <algorithm>
#include <cmath>

#include "client/call/audio_file.hpp"

namespace inkwire {
namespace {

constexpr int64_t kMaxAhead = kCallRate * 2;  // two seconds: a packet further ahead is nonsense
double ms_between(CallAudio::Clock::time_point a, CallAudio::Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

void CallAudio::add(const protocol::VoiceFrame& frame, Clock::time_point arrived) {
  auto& slot = members_[frame.member];
  if (!slot) slot = std::make_unique<Member>();
  Member& m = *slot;
  // Every packet is decoded, played or not, so the decoder's state follows the stream. A gap since
  // the member's last packet (one lost) is concealed, so the voice does not click.
  std::vector<float> pcm;
  if (m.next_ms && frame.time_ms > *m.next_ms && frame.time_ms - *m.next_ms <= 120) {
    pcm = m.decoder.conceal(int((frame.time_ms - *m.next_ms) * kCallRate / 1000));
  }
  const size_t concealed = pcm.size();
  const std::vector<float> decoded = m.decoder.decode(frame.opus);
  if (decoded.empty()) return;
  pcm.insert(pcm.end(), decoded.begin(), decoded.end());
  const double duration_ms = double(decoded.size()) * 1000.0 / kCallRate;
  const Playout placed = place_voice(frame.time_ms, duration_ms, ms_between(start_, arrived), double(mixed_until_) * 1000.0 / kCallRate, m.clock);
  if (placed.kind == Playout::Kind::Late) {
    ++late_;
    m.next_ms.reset();
    return;
  }
  m.next_ms = frame.time_ms + uint32_t(std::lround(duration_ms));
  if (placed.kind == Playout::Kind::Skip) {
    ++skipped_;
    return;
  }
  // What is played from where: the concealment just before the packet, or when the packet's start
  // is skipped, its rest alone (the gap concealed is what the offset caught up).
  size_t drop = 0;
  int64_t first = std::llround(placed.at_ms * kCallRate / 1000.0);
  if (placed.skip_ms > 0) {
    drop = std::min(pcm.size(), concealed + size_t(std::lround(placed.skip_ms * kCallRate / 1000.0)));
  } else {
    first -= int64_t(concealed);
  }
  const int64_t from = std::max(first, mixed_until_) - mixed_until_, to = first + int64_t(pcm.size() - drop) - mixed_until_;
  if (to > kMaxAhead) {
    ++late_;  // far ahead of the clock: a clock jump; start the member's mapping again
    members_.erase(frame.member);
    return;
  }
  if (int64_t(ahead_.size()) < to) ahead_.resize(size_t(to), 0.0f);
  for (int64_t i = from; i < to; ++i) ahead_[size_t(i)] += pcm[drop + size_t(i - (first - mixed_until_))];
  ++played_;
}

std::vector<float> CallAudio::take(Clock::time_point until) {
  const int64_t end = std::llround(ms_between(start_, until) * kCallRate / 1000.0);
  const int64_t n = std::max<int64_t>(end - mixed_until_, 0);
  std::vector<float> out(size_t(n), 0.0f);
  const int64_t have = std::min<int64_t>(n, int64_t(ahead_.size()));
  for (int64_t i = 0; i < have; ++i) out[size_t(i)] = std::clamp(ahead_[size_t(i)], -1.0f, 1.0f);
  ahead_.erase(ahead_.begin(), ahead_.begin() + have);
  mixed_until_ += n;
  return out;
}

std::optional<CallAudio::Clock::time_point> CallAudio::local_time(uint16_t member, uint32_t time_ms) const {
  const auto it = members_.find(member);
  if (it == members_.end()) return std::nullopt;
  const VoiceClock& clock = it->second->clock;
  const double ms = double(time_ms) + clock.offset_ms.value_or(0) + clock.delay_ms;
  return start_ + std::chrono::microseconds(std::llround(ms * 1000.0));
}

}  // namespace inkwire
