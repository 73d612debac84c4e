// Painterly and oil-filter styles (SPEC P1-P8) rendered headless: brushes stay near the object's
// matte (softly across it, or cut by it) and cover it, watercolour glazes with wet edges and
// granulation, neon glows, a still object does not flash between frames, goldens.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <gtest/gtest.h>

#include "client/gl/canvas.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/painterly/video_painter.hpp"
#include "client/render/styles.hpp"
#include "common/error.hpp"
#include "gl_test_support.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;

namespace {

// A sphere whose vertex colours change with height and longitude, so the painting has colour
// edges to follow and sample.
SceneObject coloured_sphere() {
  Mesh mesh = test::make_sphere(64, 32);
  mesh.colours.resize(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    mesh.colours[i] = {0.55f + 0.45f * p.y, 0.4f + 0.3f * std::sin(4.0f * std::atan2(p.z, p.x)), 0.6f - 0.4f * p.y, 1.0f};
  }
  return make_scene_object(std::move(mesh));
}

}  // namespace

TEST(PainterlyGLTest, BrushesStayNearTheMatteAndCoverTheObject) {
  test::offscreen_context();
  Canvas canvas(320, 320);
  const SceneObject sphere = coloured_sphere();
  const FrameState frame = test::view_of(sphere, canvas, 20, 10, 1.6f);
  auto reference = make_renderer("default");
  reference->prepare(sphere);
  const Image mask = test::render_frame(*reference, frame, canvas);
  for (const char* style : {"impressionist", "pointillist", "watercolour"}) {
    for (const char* softness : {"-1", "0"}) {
      // No base coat: only brushes paint, so coverage is theirs.
      auto painter = make_renderer("painterly", {std::string("style=") + style, "underpaint=0", "settle=100", std::string("edge_softness=") + softness});
      painter->prepare(sphere);
      const Image paint = test::render_frame(*painter, frame, canvas);
      // Soft edges let paint cross the outline by a share of a brush (at most half of one in
      // the shipped styles), fading; a hard edge cuts it where the matte's linear filtering
      // ends, a pixel out.
      const bool soft = std::string(softness) != "0";
      const int reach = soft ? 1 + int(std::ceil(0.5 * painter->counters().at("brush_side_px"))) : 1;
      size_t object = 0, covered = 0, outside = 0, partial_outside = 0;
      for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
          const bool inside = mask.rgba(x, y).a > 0;
          const uint8_t a = paint.rgba(x, y).a;
          if (inside) {
            ++object, covered += a >= 24;  // any paint: watercolour washes are thin
          } else if (a > 0) {
            outside += !test::near_covered(mask, x, y, reach);
            partial_outside += !test::near_covered(mask, x, y, 1) && a < 200;
          }
        }
      std::printf("%s, edge_softness=%s: %.4f of %zu object pixels painted, %zu painted beyond %d pixels, %zu fading across the outline\n",
                  style, softness, double(covered) / double(object), object, outside, reach, partial_outside);
      EXPECT_EQ(outside, 0u) << style << ": a brush painted beyond the reach of the object's matte";
      // Pointillism leaves gaps between dots by design (coverage 0.9 in its style file), and
      // watercolour lets the paper show between its few broad washes (base coat off here).
      const double least = std::string(style) == "pointillist" ? 0.85 : std::string(style) == "watercolour" ? 0.9 : 0.97;
      EXPECT_GE(double(covered) / double(object), least) << style;
      // Small round dots seldom reach past the outline; strokes and washes often do.
      if (soft) {
        EXPECT_GT(partial_outside, std::string(style) == "pointillist" ? 5u : 100u) << style << ": paint should fade across the outline";
      }
    }
  }
}

namespace {

double luminance(glm::u8vec4 c) { return (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b) / 255.0; }

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i] / double(a.size()), mb += b[i] / double(b.size());
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < a.size(); ++i) ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma), bb += (b[i] - mb) * (b[i] - mb);
  return ab / std::sqrt(std::max(aa * bb, 1e-12));
}

// The backdrop alone, as a picture.
Image backdrop_only(const std::string& spec, int width, int height) {
  Canvas c(width, height);
  c.bind();
  Backdrop(BackdropSpec::parse(spec)).draw();
  return c.read();
}

// Each pixel less the mean of the 5 x 5 pixels around it: the paper's grain, not the shading.
std::vector<double> fine_detail(const Image& picture, const Image& mask) {
  std::vector<double> out;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (mask.rgba(x, y).a == 0) continue;
      double around = 0;
      int n = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int nx = std::clamp(x + dx, 0, picture.width - 1), ny = std::clamp(y + dy, 0, picture.height - 1);
          around += luminance(picture.rgba(nx, ny)), ++n;
        }
      out.push_back(luminance(picture.rgba(x, y)) - around / n);
    }
  return out;
}

// The shipped watercolour style with some keys replaced, as a style file of its own.
std::string watercolour_with(const std::string& replacements) {
  const std::filesystem::path file = test::scratch_dir() / ("watercolour-" + std::to_string(std::hash<std::string>{}(replacements)) + ".json");
  std::ofstream(file) << R"({"name": "watercolour variant", "brushes": 260, "shapes": ["wash"], "coverage": 0.99, "opacity": 0.5,
    "underpaint": 0.3, "blend": "glaze", "edge_softness": 0.45, "palette": {"kind": "natural", "saturation": 0.85},
    "orientation": {"kind": "circular"}, )" << replacements << "}";
  return file.string();
}

}  // namespace

// Watercolour over paper: the paint is transparent (the paper's grain shows through it, which
// opaque paint hides), pigment gathers at the wash's edge (wet edges) and settles in the
// paper's valleys (granulation). Each is measured against the same style without it.
TEST(PainterlyGLTest, WatercolourGlazesWithWetEdgesAndGranulation) {
  test::offscreen_context();
  Canvas canvas(320, 320);
  const SceneObject sphere = coloured_sphere();
  const FrameState frame = test::view_of(sphere, canvas, 20, 10, 1.6f);
  auto reference = make_renderer("default");
  reference->prepare(sphere);
  const Image mask = test::render_frame(*reference, frame, canvas);
  const Image paper = backdrop_only("paper", 320, 320);
  auto paint = [&](const std::string& style) {
    auto r = make_renderer("painterly", {"style=" + style});
    r->prepare(sphere);
    return test::render_frame(*r, frame, canvas, "paper");
  };
  // How far each object pixel lies inside the outline (up to 9 pixels), for the wet band.
  auto depth_inside = [&](int x, int y) {
    for (int d = 1; d <= 9; ++d)
      if (!test::near_covered(mask, x, y, 0) || [&] {
            for (int dy = -d; dy <= d; ++dy)
              for (int dx = -d; dx <= d; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= mask.width || ny >= mask.height || mask.rgba(nx, ny).a == 0) return true;
              }
            return false;
          }())
        return d;
    return 10;
  };
  const Image tooth = paper_tooth(512);
  struct Figures {
    double through_paper, band_darkness, inner_darkness, grain;
  };
  auto measure = [&](const Image& picture) {
    std::vector<double> ratio, teeth;
    double band = 0, inner = 0;
    size_t band_n = 0, inner_n = 0;
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x) {
        if (mask.rgba(x, y).a == 0) continue;
        const double l = luminance(picture.rgba(x, y)), p = luminance(paper.rgba(x, y));
        ratio.push_back(l / std::max(p, 1e-3));
        // The tooth map lies as the paper does: one texel per window pixel, window y up.
        teeth.push_back(tooth.rgba(x % 512, (mask.height - 1 - y) % 512).r / 255.0);
        const int d = depth_inside(x, y);
        if (d <= 2) band += 1.0 - ratio.back(), ++band_n;
        if (d >= 8) inner += 1.0 - ratio.back(), ++inner_n;
      }
    return Figures{correlation(fine_detail(picture, mask), fine_detail(paper, mask)), band / double(std::max<size_t>(band_n, 1)),
                   inner / double(std::max<size_t>(inner_n, 1)), correlation(ratio, teeth)};
  };
  const Figures shipped = measure(paint("watercolour")), opaque = measure(paint("impressionist"));
  const Figures dry_edges = measure(paint(watercolour_with(R"("wet_edges": 0, "granulation": 0.6)")));
  const Figures wet_edges = measure(paint(watercolour_with(R"("wet_edges": 0.8, "granulation": 0.6)")));
  const Figures smooth = measure(paint(watercolour_with(R"("wet_edges": 0.8, "granulation": 0)")));
  for (const auto& [name, f] : {std::pair{"watercolour", shipped}, {"impressionist", opaque}, {"no wet edges", dry_edges},
                                {"wet edges", wet_edges}, {"no granulation", smooth}})
    std::printf("%-14s paper through paint %.3f, darkening at the edge %.3f, inside %.3f, paint density with the paper's tooth %.3f\n", name,
                f.through_paper, f.band_darkness, f.inner_darkness, f.grain);
  EXPECT_GT(shipped.through_paper, 0.3) << "watercolour is transparent: the paper's grain shows through it";
  EXPECT_LT(opaque.through_paper, shipped.through_paper - 0.15) << "opaque paint hides the paper more";
  EXPECT_GT(wet_edges.band_darkness - wet_edges.inner_darkness, dry_edges.band_darkness - dry_edges.inner_darkness + 0.05)
      << "pigment should gather where the wash ends";
  EXPECT_GT(wet_edges.grain, smooth.grain + 0.1) << "pigment should settle in the paper's valleys (darker where the tooth is low)";
}

// Neon gives off light: the ground just beyond the outline is lit in the paint's colours, and
// not without the glow.
TEST(PainterlyGLTest, NeonGlowsAroundThePaint) {
  test::offscreen_context();
  Canvas canvas(320, 320);
  const SceneObject sphere = coloured_sphere();
  const FrameState frame = test::view_of(sphere, canvas, 20, 10, 1.6f);
  auto reference = make_renderer("default");
  reference->prepare(sphere);
  const Image mask = test::render_frame(*reference, frame, canvas);
  const std::string ground = default_backdrop("painterly", {"style=neon"});
  EXPECT_NE(ground, default_backdrop("painterly")) << "neon names its own dark ground";
  auto halo = [&](const std::string& glow) {
    auto r = make_renderer("painterly", {"style=neon", "glow=" + glow});
    r->prepare(sphere);
    const Image picture = test::render_frame(*r, frame, canvas, ground);
    const Image bare = backdrop_only(ground, canvas.width(), canvas.height());
    double lift = 0;
    size_t n = 0;
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x)
        if (!test::near_covered(mask, x, y, 3) && test::near_covered(mask, x, y, 12))
          lift += luminance(picture.rgba(x, y)) - luminance(bare.rgba(x, y)), ++n;
    std::printf("neon, glow=%s: the ground 3-12 pixels beyond the outline lifted by %.4f\n", glow.c_str(), lift / double(n));
    return lift / double(n);
  };
  // The ground's own luminance is 0.08: lit by a quarter of that or more (measured +0.038).
  EXPECT_GT(halo("-1"), 0.02);
  EXPECT_LT(halo("0"), 0.002);
}

TEST(PainterlyGLTest, AStillObjectDoesNotFlash) {
  test::offscreen_context();
  Canvas canvas(256, 256);
  const SceneObject sphere = coloured_sphere();
  FrameState frame = test::view_of(sphere, canvas, 0, 0, 1.6f);
  auto painter = make_renderer("painterly", {"style=impressionist"});
  painter->prepare(sphere);
  Image previous = test::render_frame(*painter, frame, canvas, "#ffffff");
  double worst = 0;
  for (int f = 1; f <= 20; ++f) {
    frame.frame = f;
    frame.time_seconds = f / 30.0;
    const Image next = test::render_frame(*painter, frame, canvas, "#ffffff");
    double diff = 0;
    for (size_t i = 0; i < next.pixels.size(); ++i) diff += std::abs(int(next.pixels[i]) - int(previous.pixels[i]));
    worst = std::max(worst, diff / double(next.pixels.size()));
    previous = next;
  }
  std::printf("worst mean change between frames: %.3f\n", worst);
  // Brushes drift a pixel or so and colours are averaged: consecutive frames stay close. A
  // respawn wave or re-scattered field changes far more (mean about 10).
  EXPECT_LT(worst, 3.0);
  const auto counters = painter->counters();
  EXPECT_GE(counters.at("visible_fraction"), 0.95);
}

TEST(PainterlyGLTest, PaintingAPaintingIsRefused) {
  test::offscreen_context();
  EXPECT_THROW(make_renderer("painterly", {"reference=painterly"}), Error);
  EXPECT_THROW(make_renderer("painterly", {"style=no-such-style"}), Error);
  EXPECT_NO_THROW(make_renderer("painterly", {"reference=comic-extended"}));
}

class PainterlyGoldenGLTest : public ::testing::TestWithParam<std::string> {};

// Fixed view and seed, settled brushes. The simulation is deterministic; the tolerance covers
// llvmpipe rounding on brush edges only.
TEST_P(PainterlyGoldenGLTest, MatchesGolden) {
  const auto duck = test::kAssimpModels / "Collada/duck.dae";
  INKWIRE_REQUIRE_FILE(duck);
  test::offscreen_context();
  Canvas canvas(320, 240);
  const SceneObject object = load_scene_object(duck);
  const std::string style = GetParam();
  auto renderer = style == "oil-filter" ? make_renderer("oil-filter") : make_renderer("painterly", {"style=" + style});
  renderer->prepare(object);
  // Over the ground the style is meant for, as a user sees it (watercolour's paper, neon's dark).
  const std::string ground = style == "oil-filter" ? default_backdrop("oil-filter") : default_backdrop("painterly", {"style=" + style});
  const Image img = test::render_frame(*renderer, test::view_of(object, canvas, 30, 20, 1.1f), canvas, ground);
  std::string name = "painterly_" + style;
  std::replace(name.begin(), name.end(), '-', '_');
  EXPECT_EQ(test::compare_with_golden(img, name, {24, 0.01, 0.5}), "");
}

INSTANTIATE_TEST_SUITE_P(ShippedStyles, PainterlyGoldenGLTest,
                         ::testing::Values("impressionist", "pointillist", "watercolour", "neon", "sepia-study", "oil-filter"),
                         [](const auto& info) {
                           std::string n = info.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// Video painting (SPEC P9): each frame painted over the last; a still scene settles instead of
// flashing, and the painting keeps the frame's colours.
TEST(VideoPainterGLTest, PaintsOverThePreviousFrameWithoutFlashing) {
  test::offscreen_context();
  Canvas canvas(160, 120);
  Image frame(160, 120);
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) {
      uint8_t* p = frame.at(x, y);
      p[0] = x < 80 ? 220 : 30, p[1] = y < 60 ? 40 : 180, p[2] = 90, p[3] = 255;
    }
  VideoPainter painter(load_paint_style("impressionist"), 1);
  canvas.bind();
  Image previous;
  double worst_change = 0, colour_error = 0;
  for (int f = 0; f < 12; ++f) {
    canvas.bind();
    painter.paint(frame);
    const Image painting = canvas.read();
    colour_error = 0;
    for (size_t i = 0; i < painting.pixels.size(); ++i) colour_error += std::abs(int(painting.pixels[i]) - int(frame.pixels[i]));
    colour_error /= double(painting.pixels.size());
    if (f > 0) {
      double change = 0;
      for (size_t i = 0; i < painting.pixels.size(); ++i) change += std::abs(int(painting.pixels[i]) - int(previous.pixels[i]));
      worst_change = std::max(worst_change, change / double(painting.pixels.size()));
    }
    previous = painting;
  }
  std::printf("video: worst mean change %.2f, mean colour error %.2f\n", worst_change, colour_error);
  EXPECT_LT(worst_change, 6.0) << "strokes drift and recolour; the picture is not redone each frame";
  EXPECT_LT(colour_error, 25.0) << "the painting keeps the frame's colours (strokes add texture, not new colours)";
}
