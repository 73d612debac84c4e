#pragma once
// A small, fast, deterministic generator (SplitMix64): the same seed gives the same strokes,
// brushes and views on every machine, unlike std:: distributions whose output is unspecified.
#include <cstdint>

namespace inkwire {

class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [lo, hi).
  float uniform(float lo, float hi) { return lo + (hi - lo) * float(next() >> 40) / float(1ull << 24); }
  // Uniform integer in [lo, hi].
  int between(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }

 private:
  uint64_t state_;
};

// Mixes numbers into one seed (edge id, repetition, boil step, brush id, ...).
inline uint64_t mix_seed(uint64_t a, uint64_t b, uint64_t c = 0) {
  Random r(a * 0x9e3779b97f4a7c15ull ^ (b + 0x632be59bd9b4e019ull) ^ (c << 17));
  return r.next();
}

}  // namespace inkwire
