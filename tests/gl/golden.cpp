#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "common/error.hpp"
#include "gl_test_support.hpp"

namespace inkwire::test {

Context& offscreen_context() {
  static std::unique_ptr<Context> context = create_offscreen_context(64, 64);
  context->make_current();
  return *context;
}

std::string compare_with_golden(const Image& actual, const std::string& name, const GoldenTolerance& tol) {
  const std::filesystem::path golden = std::filesystem::path(INKWIRE_GOLDEN_DIR) / (name + ".png");
  const std::filesystem::path out_dir = INKWIRE_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(out_dir);
  if (const char* approve = std::getenv("INKWIRE_APPROVE_GOLDEN"); approve && std::string(approve) == "1") {
    save_image(actual, golden);
    return "";
  }
  if (!std::filesystem::exists(golden)) {
    save_image(actual, out_dir / (name + ".actual.png"));
    return "no golden image " + golden.string() + ": look at " + (out_dir / (name + ".actual.png")).string() +
           ", then approve with INKWIRE_APPROVE_GOLDEN=1";
  }
  const Image expected = load_image(golden);
  auto fail = [&](const std::string& why) {
    save_image(actual, out_dir / (name + ".actual.png"));
    if (expected.width == actual.width && expected.height == actual.height) {
      Image diff(actual.width, actual.height, {0, 0, 0, 255});
      for (size_t i = 0; i < diff.pixels.size(); i += 4)
        for (int c = 0; c < 3; ++c)
          diff.pixels[i + c] = uint8_t(std::min(255, 4 * std::abs(int(actual.pixels[i + c]) - int(expected.pixels[i + c]))));
      save_image(diff, out_dir / (name + ".diff.png"));
    }
    return why + " (see " + (out_dir / (name + ".actual.png")).string() + " and .diff.png)";
  };
  if (expected.width != actual.width || expected.height != actual.height) return fail("size differs from golden");
  size_t different = 0;
  double sum = 0;
  for (size_t i = 0; i < actual.pixels.size(); i += 4) {
    int worst = 0;
    for (int c = 0; c < 4; ++c) {
      const int d = std::abs(int(actual.pixels[i + c]) - int(expected.pixels[i + c]));
      worst = std::max(worst, d);
      sum += d;
    }
    different += worst > tol.max_channel_diff;
  }
  const double pixels = double(actual.width) * actual.height;
  const double fraction = different / pixels, mean = sum / (pixels * 4);
  if (fraction > tol.max_different_fraction || mean > tol.max_mean_diff) {
    std::ostringstream s;
    s << name << ": " << different << " pixels (" << fraction * 100 << "%) differ by more than " << tol.max_channel_diff
      << ", mean difference " << mean;
    return fail(s.str());
  }
  return "";
}

}  // namespace inkwire::test
