#pragma once
// Shared pieces of the headless GL tests: one OSMesa context per test process, and golden image
// comparison that writes actual and diff images on failure.
#include <string>

#include "client/gl/context.hpp"
#include "common/image.hpp"

namespace inkwire::test {

// The process-wide off-screen context (made current on first use).
Context& offscreen_context();

struct GoldenTolerance {
  int max_channel_diff;        // a pixel counts as different above this (0..255)
  double max_different_fraction;  // fraction of pixels allowed to differ
  double max_mean_diff;        // mean absolute channel difference over the image
};

// Compares `actual` with tests/golden/<name>.png. On failure writes <name>.actual.png and
// <name>.diff.png into the test output folder and returns a description; returns "" on success.
// With INKWIRE_APPROVE_GOLDEN=1 in the environment it (over)writes the golden image instead.
std::string compare_with_golden(const Image& actual, const std::string& name, const GoldenTolerance& tolerance);

}  // namespace inkwire::test
