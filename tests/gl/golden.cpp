#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "client/render/backdrop.hpp"
#include "common/error.hpp"
#include "gl_test_support.hpp"

namespace inkwire::test {

Context& offscreen_context() {
  static std::unique_ptr<Context> context = create_offscreen_context(64, 64);
  context->make_current();
  return *context;
}

Image render_frame(Renderer& renderer, const FrameState& frame, const Canvas& canvas, const std::string& backdrop) {
  canvas.bind();
  const Backdrop under(BackdropSpec::parse(backdrop));
  under.draw();
  FrameState with_backdrop = frame;
  with_backdrop.backdrop = &under;
  renderer.draw(with_backdrop);
  return canvas.read();
}

Mesh make_sphere(int segments, int rings) {
  Mesh m;
  m.positions.push_back({0, 1, 0});  // north pole
  for (int r = 1; r < rings; ++r) {
    const float theta = float(M_PI) * r / rings;
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * float(M_PI) * s / segments;
      m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
    }
  }
  const uint32_t south = uint32_t(m.positions.size());
  m.positions.push_back({0, -1, 0});
  auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  // Counter-clockwise seen from outside (phi runs counter-clockwise seen from above).
  for (int s = 0; s < segments; ++s) {
    m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    m.triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
  }
  for (int r = 1; r < rings - 1; ++r)
    for (int s = 0; s < segments; ++s) {
      m.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
      m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
    }
  m.materials.emplace_back();
  return m;
}

bool near_covered(const Image& mask, int x, int y, int reach) {
  for (int v = std::max(0, y - reach); v <= std::min(mask.height - 1, y + reach); ++v)
    for (int u = std::max(0, x - reach); u <= std::min(mask.width - 1, x + reach); ++u)
      if (mask.rgba(u, v).a > 0) return true;
  return false;
}

Mesh make_box() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  m.triangles = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                 {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  m.materials.emplace_back();
  return m;
}

FrameState view_of(const SceneObject& object, const Canvas& canvas, float azimuth, float elevation, float distance) {
  FrameState f;
  f.viewport = canvas.size();
  f.camera = orbit_camera(object.topology.bounds, azimuth, elevation, distance);
  f.light_direction = default_light_direction(f.camera);
  return f;
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
