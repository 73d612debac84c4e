// What the browser's turntable and call voice compute in JS as the C++ client does (issue:
// one implementation of each algorithm; the warps stay in JS for the element's first-view budget,
// docs/benchmarks-journal.md; faces are drawn by the C++ itself, compiled into the browser's module): the C++ answers for fixed inputs, written to tests/golden/warp-vectors.json
// and checked by client/web/test/ (warp, turntable_pose and voice tests). A change to either side fails one of the two until
// both agree and the file is approved again (INKWIRE_APPROVE_GOLDEN=1).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/call/face_crop.hpp"
#include "client/gl/resources.hpp"
#include "client/call/playout_delay.hpp"
#include "client/render/tween/matte_sample.hpp"
#include "client/viewer/photo_fetch.hpp"
#include "client/viewer/turntable_view.hpp"
#include "client/viewer/window_input.hpp"
#include "common/camera.hpp"
#include "common/distance_field.hpp"
#include "common/tween/view_sphere.hpp"
#include "common/tween/warp_mesh.hpp"

namespace inkwire {
namespace {

std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) | (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    for (size_t k = 0; k < 4; ++k) out += i + k <= bytes.size() ? digits[(n >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

// A deterministic stream in [0, 1): the same points on every run and machine.
struct Lcg {
  uint32_t state = 12345;
  double next() { return double((state = state * 1664525u + 1013904223u) >> 8) / double(1 << 24); }
};

nlohmann::json triangles_json(const std::vector<std::array<uint32_t, 3>>& triangles) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : triangles) out.push_back({t[0], t[1], t[2]});
  return out;
}

// Point sets with what makes triangulations differ: four points on a circle (a grid, the image
// border), points nearer than 1/8 pixel, collinear rows.
nlohmann::json delaunay_cases() {
  nlohmann::json cases = nlohmann::json::array();
  std::vector<glm::dvec2> grid;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) grid.push_back({40.0 * x, 30.0 * y});
  Lcg random;
  std::vector<glm::dvec2> scattered;
  for (int i = 0; i < 80; ++i) scattered.push_back({random.next() * 512, random.next() * 384});
  for (int i = 0; i < 10; ++i) scattered.push_back(scattered[size_t(i) * 7] + glm::dvec2(random.next() * 0.08, random.next() * 0.08));
  for (const glm::vec2& b : border_points(512, 384)) scattered.push_back(b);
  std::vector<glm::dvec2> line{{0, 0}, {10, 0}, {20, 0}, {30, 0}, {15, 10}, {15, -10}, {15, 0.05}};
  for (const auto& [name, points] : {std::pair{"grid", grid}, {"scattered with near twins and the border", scattered}, {"a row", line}}) {
    nlohmann::json p = nlohmann::json::array();
    for (const glm::dvec2& v : points) p.push_back({v.x, v.y});
    cases.push_back({{"name", name}, {"points", p}, {"triangles", triangles_json(delaunay_triangles(points))}});
  }
  return cases;
}

// Cells as tween data carries them (positions in 1/8 pixels), a pair and a triangle.
nlohmann::json warp_mesh_cases() {
  nlohmann::json cases = nlohmann::json::array();
  Lcg random;
  for (const std::vector<uint16_t>& samples : {std::vector<uint16_t>{0, 1}, std::vector<uint16_t>{0, 1, 2}}) {
    TweenCell cell{.samples = samples, .points = {}};
    for (int i = 0; i < 40; ++i) {
      ControlPoint p;
      for (glm::vec2& v : p) v = glm::vec2(std::floor(random.next() * 4096) / 8, std::floor(random.next() * 3072) / 8);
      cell.points.push_back(p);
    }
    nlohmann::json points = nlohmann::json::array();
    for (const ControlPoint& p : cell.points) points.push_back({{p[0].x, p[0].y}, {p[1].x, p[1].y}, {p[2].x, p[2].y}});
    const WarpMesh mesh = build_warp_mesh(cell, 512, 384);
    cases.push_back({{"samples", samples}, {"points", points}, {"width", 512}, {"height", 384},
                     {"mesh_points", mesh.points.size()}, {"triangles", triangles_json(mesh.triangles)}});
  }
  return cases;
}

// A product photo as a shop's: an ellipse of graded colour with a soft edge and a soft shadow
// below, laid over white; its matte; the same photo at twice the size for a finer zoom level.
nlohmann::json matte_cases() {
  nlohmann::json cases = nlohmann::json::array();
  const int w = 48, h = 36;
  Image matte(w, h, {0, 0, 0, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double r = std::hypot((x + 0.5 - 22) / 15, (y + 0.5 - 15) / 10);
      const uint8_t a = uint8_t(std::clamp((1.0 - r) * 10.0 * 255.0, 0.0, 255.0));
      uint8_t* p = matte.at(x, y);
      p[0] = p[1] = p[2] = a;
    }
  for (const int level : {1, 2}) {
    Image photo(w * level, h * level);
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) {
        const double fx = (x + 0.5) / level, fy = (y + 0.5) / level;
        const double r = std::hypot((fx - 22) / 15, (fy - 15) / 10);
        const double object = std::clamp((1.0 - r) * 10.0, 0.0, 1.0);
        const double shadow = 0.35 * std::max(0.0, 1.0 - std::hypot((fx - 22) / 18, (fy - 27) / 4));
        const double colour[3] = {200 - 3 * fx, 60 + 4 * fy, 90.0};
        uint8_t* p = photo.at(x, y);
        for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(object * colour[c] + (1 - object) * 255 * (1 - shadow)));
        p[3] = 255;
      }
    const Image object = object_on_matte(photo, matte);
    const double scale = double(photo.height) / double(h);
    cases.push_back({{"width", photo.width}, {"height", photo.height}, {"matte_width", w}, {"matte_height", h}, {"scale", scale},
                     {"photo", base64(photo.pixels)}, {"matte", base64(matte.pixels)}, {"object", base64(object.pixels)},
                     {"sample", base64(matte_sample(object, scale).pixels)}});
  }
  return cases;
}

nlohmann::json distance_case() {
  const int w = 23, h = 17;
  std::vector<uint8_t> seed(size_t(w) * h, 0);
  // Seeds that make ties: a pair in a row, a pair in a column, a diagonal run, a lone corner.
  for (const auto& [x, y] : {std::pair{5, 8}, {17, 8}, {0, 16}, {11, 2}, {12, 3}, {13, 4}, {22, 0}, {20, 10}, {20, 16}}) seed[size_t(y) * w + size_t(x)] = 1;
  const DistanceField field = distance_to_seeds(seed, w, h);
  return {{"width", w}, {"height", h}, {"seed", seed}, {"distance", field.distance}, {"nearest", field.nearest}};
}

// A ring of 12 at the equator under a ring of 12 at 30 degrees, joined by triangles as rows are.
TweenData two_rows() {
  TweenData data;
  data.directions = ring_directions(12);
  for (const glm::vec3& d : ring_directions(12, 30.0f)) data.directions.push_back(d);
  for (const auto& c : ring_cells(12)) data.cells.push_back({.samples = c, .points = {}});
  for (uint16_t i = 0; i < 12; ++i) {
    const uint16_t next = uint16_t((i + 1) % 12);
    data.cells.push_back({.samples = {i, next, uint16_t(12 + i)}, .points = {}});
    data.cells.push_back({.samples = {next, uint16_t(12 + next), uint16_t(12 + i)}, .points = {}});
  }
  return data;
}

glm::vec3 view_direction(float azimuth_degrees, float elevation_degrees) {
  const float a = glm::radians(azimuth_degrees), e = glm::radians(elevation_degrees);
  return {std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e)};
}

nlohmann::json locate_cases() {
  const TweenData data = two_rows();
  nlohmann::json directions = nlohmann::json::array(), cells = nlohmann::json::array(), views = nlohmann::json::array();
  for (const glm::vec3& d : data.directions) directions.push_back({d.x, d.y, d.z});
  for (const TweenCell& c : data.cells) cells.push_back(c.samples);
  for (const auto& [azimuth, elevation] : {std::pair{7.0f, 0.0f}, {100.0f, 0.0f}, {200.0f, 10.0f}, {-45.0f, 22.0f}, {80.0f, 60.0f}, {13.0f, -20.0f}}) {
    const glm::vec3 d = view_direction(azimuth, elevation);
    const CellLocation at = locate_view(data, d);
    views.push_back({{"direction", {d.x, d.y, d.z}}, {"cell", at.cell}, {"inside", at.inside}, {"t", at.t}, {"weights", at.weights}});
  }
  return {{"directions", directions}, {"cells", cells}, {"views", views}};
}

// The two rows and, as spin sets often end, the first photo's direction again (a tie for nearest).
TweenData two_rows_and_a_twin() {
  TweenData data = two_rows();
  data.directions.push_back(data.directions[0]);
  return data;
}

// A visitor on the two rows looks, turns and zooms (photos 300 pixels high, finer levels of 600
// and 1200), and at last, every first level there, zooms in and turns a little: the level each
// view wants and every photo fetched, in order, each taken as there, the finer levels given way
// when more than kFinerKept photos hold one, and which are held after each view.
nlohmann::json photo_fetch_cases() {
  const TweenData data = two_rows_and_a_twin();
  const int first_height = 300;
  const std::vector<int> level_heights = {600, 1200};
  std::vector<bool> has_first(data.directions.size(), false);
  std::map<int, int> finer_level;
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& [azimuth, elevation, shown, fetches] : {std::tuple{7.0f, 0.0f, 300.0, 4}, {15.0f, 15.0f, 300.0, 3}, {15.0f, 15.0f, 500.0, 4},
                                                           {15.0f, 15.0f, 1600.0, 4}, {200.0f, 30.0f, 1000.0, 7}, {45.0f, 0.0f, 375.0, 40},
                                                           {45.0f, 0.0f, 1000.0, 12}, {75.0f, 0.0f, 1000.0, 12}}) {
    const glm::vec3 d = view_direction(azimuth, elevation);
    const int wanted = wanted_level(first_height, level_heights, shown);
    nlohmann::json fetched = nlohmann::json::array(), dropped = nlohmann::json::array();
    for (int i = 0; i < fetches; ++i) {
      const auto next = next_photo_fetch(data.directions, d, view_samples(data, d), has_first, finer_level, wanted);
      if (!next) break;
      fetched.push_back({next->sample, next->level});
      if (next->level == 0) has_first[size_t(next->sample)] = true;
      else finer_level[next->sample] = next->level;
      if (const int drop = next->level > 0 ? finer_to_drop(data.directions, next->sample, finer_level) : -1; drop >= 0) {
        finer_level.erase(drop);
        dropped.push_back(drop);
      }
    }
    nlohmann::json holding = nlohmann::json::array();
    for (const auto& [sample, level] : finer_level) holding.push_back({sample, level});
    steps.push_back({{"direction", {d.x, d.y, d.z}}, {"shown", shown}, {"fetches", fetches}, {"wanted", wanted}, {"fetched", fetched},
                     {"dropped", dropped}, {"holding", holding}});
  }
  nlohmann::json directions = nlohmann::json::array(), cells = nlohmann::json::array();
  for (const glm::vec3& d : data.directions) directions.push_back({d.x, d.y, d.z});
  for (const TweenCell& c : data.cells) cells.push_back(c.samples);
  return {{"directions", directions}, {"cells", cells}, {"first_height", first_height}, {"level_heights", level_heights}, {"steps", steps}};
}

// A visitor's view shared as a pose (presenter mode) and a shared pose's zoom held to the range.
nlohmann::json turntable_cases() {
  nlohmann::json poses = nlohmann::json::array();
  for (const auto& [azimuth, elevation, zoom] : {std::tuple{30.0f, 20.0f, 1.5f}, {0.0f, 0.0f, 1.0f}, {-170.0f, 40.0f, 0.5f}, {95.0f, -80.0f, 4.0f}}) {
    const protocol::ObjectPose pose = TurntableOrbit{.azimuth = azimuth, .elevation = elevation, .zoom = zoom}.pose(7);
    poses.push_back({{"view", {azimuth, elevation, zoom}}, {"rotation", {pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w}}});
  }
  nlohmann::json held = nlohmann::json::array();
  for (const float scale : {0.1f, 1.25f, 9.0f})
    held.push_back({scale, TurntableOrbit::from_pose({.sequence = 0, .rotation = {0, 0, 0, 1}, .translation = glm::vec3(0.0f), .scale = scale}).zoom});
  return {{"zoom_range", {TurntableOrbit::kMinZoom, TurntableOrbit::kMaxZoom}}, {"poses", poses}, {"zoom_of_scale", held}};
}

// A member's 20 ms voice packets, one after another, reaching a listener when `arrived` whose
// clock has played `played` ms: a first packet that came slowly, one 18.25 ms sooner (its start
// skipped as the offset catches up), one 1.5 ms sooner (under kCatchUpMs: played whole), one
// 41 ms sooner (skipped whole), on time, 78 ms late (the delay grows), on time, 190 ms late:
// beyond the largest delay (late), then on time, then 11.5 ms sooner again.
nlohmann::json playout_cases() {
  struct Packet {
    double time, arrived, played;
  };
  const std::vector<Packet> packets = {{0, 1030.25, 1000}, {20, 1032, 1010},  {40, 1050.5, 1040},   {60, 1031, 1040},   {80, 1075, 1100},
                                       {100, 1250, 1250},  {120, 1262, 1255}, {140, 1500, 1500}, {160, 1300, 1290}, {180, 1160.5, 1295}};
  constexpr double kDuration = 20;
  VoiceClock clock;
  const char* kinds[] = {"play", "skip", "late"};
  nlohmann::json steps = nlohmann::json::array();
  for (const Packet& p : packets) {
    const Playout placed = place_voice(p.time, kDuration, p.arrived, p.played, clock);
    steps.push_back({{"time_ms", p.time}, {"duration_ms", kDuration}, {"arrived_ms", p.arrived}, {"played_ms", p.played},
                     {"kind", kinds[int(placed.kind)]}, {"at_ms", placed.at_ms}, {"skip_ms", placed.skip_ms},
                     {"offset_ms", *clock.offset_ms}, {"delay_ms", clock.delay_ms}});
  }
  return {{"limits", {kStartDelayMs, kDelayMarginMs, kMaxDelayMs, kCatchUpMs}}, {"steps", steps}};
}

// The face video's rectangle following a face the server reports (SPEC F17) in a 640 x 480
// frame: from the whole frame, then nudged, drifted, grown, jumped, shrunk by half, then a region
// cut by the frame's edge (squared and moved in) and one taller than the frame.
nlohmann::json face_crop_cases() {
  using inkwire::protocol::FaceRegion;
  const std::vector<FaceRegion> reports = {{true, 200, 100, 240, 240}, {true, 210, 105, 240, 240}, {true, 230, 100, 240, 240},
                                           {true, 230, 100, 280, 280}, {true, 400, 150, 240, 240}, {true, 400, 150, 150, 150},
                                           {true, 500, 300, 140, 180}, {true, 100, 0, 400, 480}};
  FaceRegion shown{.found = false, .x = 0, .y = 0, .width = 640, .height = 480};
  nlohmann::json steps = nlohmann::json::array();
  const auto json_of = [](const FaceRegion& r) { return nlohmann::json{{"found", r.found}, {"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}}; };
  for (const FaceRegion& reported : reports) {
    const inkwire::FaceCropChoice choice = inkwire::follow_face(shown, reported, 640, 480);
    steps.push_back({{"shown", json_of(shown)}, {"reported", json_of(reported)}, {"region", json_of(choice.region)}, {"jumped", choice.jumped}});
    shown = choice.region;
  }
  // The whole frame's picture while no face is found: landscape, portrait, small, odd sizes.
  nlohmann::json search = nlohmann::json::array();
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{640, 480}, {565, 800}, {1280, 720}, {300, 200}, {641, 479}, {20, 1000}}) {
    const inkwire::PictureSize size = inkwire::search_picture_size(w, h);
    search.push_back({{"frame", {w, h}}, {"picture", {size.width, size.height}}});
  }
  return {{"sides", {inkwire::kFaceVideoSide, inkwire::kFaceSearchWidth}}, {"steps", steps}, {"search_pictures", search}};
}

TEST(WarpVectorsTest, TheCropFollowsEveryReportAndOneThatJumpsStartsAgain) {
  const nlohmann::json steps = face_crop_cases()["steps"];
  const std::vector<bool> jumped = {true, false, false, false, true, true, true, true};
  for (size_t i = 0; i < steps.size(); ++i) {
    EXPECT_NE(steps[i]["region"], steps[i]["shown"]) << i << ": every report moves the crop";
    EXPECT_EQ(steps[i]["jumped"].get<bool>(), jumped[i]) << i;
    const auto& r = steps[i]["region"];
    EXPECT_EQ(r["width"], r["height"]) << i << ": not square";
    EXPECT_LE(r["x"].get<int>() + r["width"].get<int>(), 640) << i;
    EXPECT_LE(r["y"].get<int>() + r["height"].get<int>(), 480) << i;
  }
}

// A drag's speed and the coasting after it (the turntable's inertia), step by step: a drag of
// uneven moves, one too fast (held to a turn a second), then coasting frames at 60 Hz and a
// long frame, down to a stop.
nlohmann::json inertia_cases() {
  nlohmann::json drags = nlohmann::json::array(), coasts = nlohmann::json::array();
  float velocity = 0.0f;
  for (const auto& [degrees, seconds] : std::vector<std::pair<float, double>>{{2.0f, 0.016}, {3.5f, 0.017}, {-1.0f, 0.02}, {40.0f, 0.016}, {6.0f, 0.033}}) {
    const float next = dragged_velocity(velocity, degrees, seconds);
    drags.push_back({{"velocity", velocity}, {"degrees", degrees}, {"seconds", seconds}, {"next", next}});
    velocity = next;
  }
  for (int frame = 0; frame < 200 && velocity != 0.0f; ++frame) {
    const double seconds = frame == 5 ? 0.1 : 1.0 / 60;
    const Coasted c = coast(velocity, seconds);
    coasts.push_back({{"velocity", velocity}, {"seconds", seconds}, {"turn", c.turn}, {"next", c.velocity}});
    velocity = c.velocity;
  }
  return {{"limits", {kMaxTurnSpeed, kInertiaSeconds, kInertiaStop}}, {"drags", drags}, {"coasts", coasts}};
}

TEST(WarpVectorsTest, AFlingIsHeldToATurnASecondAndCoastsToAStop) {
  const nlohmann::json c = inertia_cases();
  EXPECT_EQ(c["drags"][3]["next"].get<float>(), kMaxTurnSpeed) << "a fast drag is held to a turn a second";
  ASSERT_FALSE(c["coasts"].empty());
  EXPECT_EQ(c["coasts"].back()["next"].get<float>(), 0.0f) << "it comes to a stop";
  double turned = 0;
  for (const auto& step : c["coasts"]) turned += step["turn"].get<double>();
  const double start = c["coasts"][0]["velocity"].get<double>();
  EXPECT_NEAR(turned, start * kInertiaSeconds, 0.1 * start * kInertiaSeconds) << "about its speed times the time constant";
}

// The turntable's framing (fit_scale) in elements of every shape: landscape and square ones wider
// than the photos, a phone held upright (390 x 844) with square and landscape photos, and
// degenerate sizes (nothing to fit).
nlohmann::json framing_cases() {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& [viewport, picture] : std::vector<std::pair<float, float>>{{620.0f / 500, 1}, {1, 1}, {1, 4.0f / 3}, {390.0f / 844, 1},
                                                                              {390.0f / 844, 640.0f / 480}, {844.0f / 390, 600.0f / 338}, {0, 1}})
    cases.push_back({{"viewport_aspect", viewport}, {"picture_aspect", picture}, {"scale", fit_scale(viewport, picture)}});
  return cases;
}

TEST(WarpVectorsTest, APortraitViewportShowsTheWholePictureAndAWideOneItsFullHeight) {
  EXPECT_FLOAT_EQ(fit_scale(620.0f / 500, 1), 1.0f) << "wider than the picture: full height";
  EXPECT_NEAR(fit_scale(390.0f / 844, 1) * 844, 390, 1e-3) << "upright phone: the picture as wide as the screen";
  // A scene's field of view spans the width of a portrait viewport: a point at the edge of a
  // square viewport's field lands at the edge of a portrait one's width.
  Camera c;
  const glm::vec4 edge(std::tan(glm::radians(c.fov_y_degrees) / 2.0f), 0.0f, -1.0f, 1.0f);
  const glm::vec4 square = c.projection(1.0f) * edge, portrait = c.projection(390.0f / 844) * edge;
  EXPECT_NEAR(square.x / square.w, 1.0f, 1e-5f);
  EXPECT_NEAR(portrait.x / portrait.w, 1.0f, 1e-5f) << "the object's width fits the phone's";
  const glm::vec4 wide = c.projection(2.0f) * glm::vec4(0.0f, edge.x, -1.0f, 1.0f);
  EXPECT_NEAR(wide.y / wide.w, 1.0f, 1e-5f) << "a landscape viewport keeps fov_y across its height";
}

TEST(WarpVectorsTest, GoldenVectorsForTheWebClientAreTheseNumbers) {
  const nlohmann::json golden = {{"delaunay", delaunay_cases()}, {"warp_meshes", warp_mesh_cases()}, {"distance_field", distance_case()},
                                 {"matte_samples", matte_cases()}, {"locate_view", locate_cases()}, {"photo_fetch", photo_fetch_cases()},
                                 {"turntable", turntable_cases()}, {"playout", playout_cases()},
                                 {"face_crop", face_crop_cases()}, {"inertia", inertia_cases()}, {"framing", framing_cases()},
                                 {"shader_header", gl::kWebGlShaderHeader}};
  const std::filesystem::path file = std::filesystem::path(INKWIRE_GOLDEN_DIR) / "warp-vectors.json";
  if (const char* approve = std::getenv("INKWIRE_APPROVE_GOLDEN"); approve && std::string(approve) == "1") {
    std::ofstream(file) << golden.dump() << "\n";
    GTEST_SKIP() << "approved " << file;
  }
  std::ifstream in(file);
  ASSERT_TRUE(in) << file << " is missing: approve it with INKWIRE_APPROVE_GOLDEN=1";
  const nlohmann::json stored = nlohmann::json::parse(in);
  for (const auto& [key, value] : golden.items())
    EXPECT_EQ(stored.at(key), value) << key << " changed: make client/web agree (node --test client/web/test/) and approve " << file;
}

// The properties the vectors stand for, so an approved file cannot hold a wrong answer.
TEST(WarpVectorsTest, TheDistanceFieldIsExactAndNamesANearestSeed) {
  const nlohmann::json c = distance_case();
  const int w = c["width"], h = c["height"];
  const std::vector<uint8_t> seed = c["seed"];
  const std::vector<double> distance = c["distance"];
  const std::vector<int32_t> nearest = c["nearest"];
  for (int i = 0; i < w * h; ++i) {
    double best = 1e9;
    for (int s = 0; s < w * h; ++s)
      if (seed[size_t(s)]) best = std::min(best, std::hypot(double(i % w - s % w), double(i / w - s / w)));
    EXPECT_DOUBLE_EQ(distance[size_t(i)], best) << "pixel " << i;
    const int s = nearest[size_t(i)];
    ASSERT_TRUE(s >= 0 && seed[size_t(s)]) << "pixel " << i;
    EXPECT_DOUBLE_EQ(std::hypot(double(i % w - s % w), double(i / w - s / w)), best) << "pixel " << i;
  }
  EXPECT_EQ(distance_to_seeds(std::vector<uint8_t>(12, 0), 4, 3).nearest, std::vector<int32_t>(12, -1));
}

TEST(WarpVectorsTest, DelaunayTrianglesHaveNoPointInsideTheirCircleAndCoverTheBorder) {
  for (const nlohmann::json& c : delaunay_cases()) {
    std::vector<glm::dvec2> points;
    for (const auto& p : c["points"]) points.push_back({p[0].get<double>(), p[1].get<double>()});
    glm::dvec2 lo(1e9), hi(-1e9);
    for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    std::vector<bool> vertex(points.size(), false);
    for (const auto& t : c["triangles"])
      for (const auto& v : t) vertex[v.get<size_t>()] = true;
    double area = 0;
    for (const auto& t : c["triangles"]) {
      const glm::dvec2 a = points[t[0]], b = points[t[1]], d = points[t[2]];
      const double twice = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
      area += std::abs(twice) / 2;
      // No vertex strictly inside the circumcircle (in-circle determinant, orientation-corrected;
      // four points on one circle give 0 up to rounding).
      for (size_t i = 0; i < points.size(); ++i) {
        if (!vertex[i]) continue;  // a near twin left out
        const glm::dvec2 u = a - points[i], v = b - points[i], q = d - points[i];
        const double in = (u.x * u.x + u.y * u.y) * (v.x * q.y - q.x * v.y) - (v.x * v.x + v.y * v.y) * (u.x * q.y - q.x * u.y) +
                          (q.x * q.x + q.y * q.y) * (u.x * v.y - v.x * u.y);
        EXPECT_LE(in * (twice > 0 ? 1 : -1), 1e-9 * std::pow(extent, 4)) << c["name"] << ": point " << i;
      }
    }
    if (c["name"] != "a row") {
      EXPECT_NEAR(area, (hi.x - lo.x) * (hi.y - lo.y), 1e-6 * (hi.x - lo.x) * (hi.y - lo.y)) << c["name"];
    }
  }
}

TEST(WarpVectorsTest, PhotosComeForTheViewFirstThenItsLevelThenNearestFirst) {
  const nlohmann::json c = photo_fetch_cases();
  const TweenData data = two_rows_and_a_twin();
  // The first view: its pair's photos, nearest first (7 degrees: the photo at 0, then at 30).
  EXPECT_EQ(c["steps"][0]["fetched"][0], nlohmann::json({0, 0}));
  EXPECT_EQ(c["steps"][0]["fetched"][1], nlohmann::json({1, 0}));
  // Zoomed between the rows: the triangle's photos at the level the view wants, before any other.
  EXPECT_EQ(c["steps"][2]["wanted"], 1);
  EXPECT_EQ(c["steps"][3]["wanted"], 2);
  for (int step : {2, 3})
    for (const auto& f : c["steps"][step]["fetched"]) {
      const std::vector<int> drawn_from = view_samples(data, view_direction(15.0f, 15.0f));
      EXPECT_NE(std::find(drawn_from.begin(), drawn_from.end(), f[0].get<int>()), drawn_from.end()) << f;
      EXPECT_EQ(f[1], c["steps"][step]["wanted"]) << f;
    }
  // Turned to the far side zoomed in, the finer levels farthest from there give way.
  EXPECT_EQ(c["steps"][4]["dropped"].size(), 1u);
  // Of the twins, the first is the nearest; the second comes when it is the nearest not there.
  EXPECT_EQ(nearest_sample(data.directions, data.directions[24]), 0);
  EXPECT_EQ(c["steps"][0]["fetched"][2], nlohmann::json({24, 0}));
  // In the end every photo's first level is there, each fetched once.
  std::set<int> first;
  for (const auto& step : c["steps"])
    for (const auto& f : step["fetched"])
      if (f[1] == 0) {
        EXPECT_TRUE(first.insert(f[0].get<int>()).second) << "photo " << f[0] << " fetched twice";
      }
  EXPECT_EQ(first.size(), data.directions.size());
  EXPECT_TRUE(c["steps"][5]["fetched"].size() < c["steps"][5]["fetches"].get<size_t>()) << "the view not zoomed in ran out of photos to fetch";
  // Every first level there and zoomed in, still and then turned a little: the view's photos at
  // its level first, then photos nearest the view ahead of the turn, till kFinerKept hold the level
  // (none drawn from given way) and one more would push out one as near: a still view stops fetching.
  for (int step : {6, 7}) {
    const nlohmann::json& s = c["steps"][step];
    const glm::vec3 d(s["direction"][0].get<float>(), s["direction"][1].get<float>(), s["direction"][2].get<float>());
    const std::vector<int> drawn_from = view_samples(data, d);
    EXPECT_LT(s["fetched"].size(), s["fetches"].get<size_t>()) << "step " << step << " ran out of photos to fetch";
    bool ahead = false;  // once a photo not drawn from is fetched, no drawn-from one follows
    for (const auto& f : s["fetched"]) {
      const bool drawn = std::find(drawn_from.begin(), drawn_from.end(), f[0].get<int>()) != drawn_from.end();
      EXPECT_FALSE(ahead && drawn) << "step " << step << " fetched photo " << f[0] << " of the view after one ahead of it";
      ahead = ahead || !drawn;
    }
    ASSERT_EQ(s["holding"].size(), size_t(kFinerKept)) << "step " << step;
    std::map<int, int> held;
    for (const auto& h : s["holding"]) {
      EXPECT_EQ(h[1], s["wanted"]) << "step " << step << " holds photo " << h[0] << " at another level";
      held[h[0].get<int>()] = h[1].get<int>();
    }
    // Why it stopped: the nearest photo lacking the level would push out one as near the view.
    const int next = nearest_sample(data.directions, d, [&](int i) { return !held.contains(i); });
    std::map<int, int> with_next = held;
    with_next[next] = s["wanted"].get<int>();
    const int pushed_out = finer_to_drop(data.directions, next, with_next);
    EXPECT_GE(nearness(data.directions[size_t(pushed_out)], d), nearness(data.directions[size_t(next)], d)) << "step " << step;
    for (int f : drawn_from)
      EXPECT_TRUE(std::any_of(s["holding"].begin(), s["holding"].end(), [&](const auto& h) { return h[0] == f; })) << "step " << step << ": " << f;
  }
  EXPECT_GT(c["steps"][7]["fetched"].size(), 0u) << "turned, the photos the turn came to are fetched";
  EXPECT_LE(c["steps"][7]["fetched"].size(), c["steps"][7]["dropped"].size() + 1) << "a small turn swaps a few, it does not fetch all again";
}

// What the playout vectors stand for: a packet plays no earlier than the clock has played and,
// when it follows the one before, exactly where that one's part played ended unless the delay
// grew (nothing overlaps, nothing gaps, skipped starts and whole skips included); the offset
// never grows and moves only for a packet kCatchUpMs sooner; the delay never shrinks, grows only
// for a late packet, by its lateness and the margin, and stays within the largest; a packet
// beyond it plays nothing and changes nothing.
TEST(WarpVectorsTest, TheVoiceRuleCatchesUpWithQuickPacketsAndWaitsForLateOnesWithoutOverlapOrGap) {
  const nlohmann::json c = playout_cases();
  std::optional<double> offset, ends;  // the offset so far, and where the last packet's played part ends
  double delay = kStartDelayMs;
  std::map<std::string, int> kinds;
  int raised = 0;
  for (const nlohmann::json& step : c["steps"]) {
    const double time = step["time_ms"], arrived = step["arrived_ms"], played = step["played_ms"], duration = step["duration_ms"];
    const std::string kind = step["kind"];
    ++kinds[kind];
    const double sooner = offset ? *offset - (arrived - time) : 0;
    EXPECT_LE(step["offset_ms"].get<double>(), offset.value_or(1e9)) << "packet " << time;
    EXPECT_GE(step["delay_ms"].get<double>(), delay);
    EXPECT_LE(step["delay_ms"].get<double>(), kMaxDelayMs);
    if (kind == "late") {
      EXPECT_EQ(step["delay_ms"].get<double>(), delay) << "packet " << time;
      ends.reset();
    } else if (kind == "skip") {
      EXPECT_GE(sooner, duration) << "packet " << time;
      EXPECT_DOUBLE_EQ(step["offset_ms"].get<double>(), *offset - duration);
    } else {
      const double at = step["at_ms"], skip = step["skip_ms"];
      EXPECT_GE(at, played) << "packet " << time;
      EXPECT_EQ(skip > 0, sooner >= kCatchUpMs) << "packet " << time;
      if (step["delay_ms"].get<double>() > delay) {
        ++raised;
        EXPECT_DOUBLE_EQ(at, played + kDelayMarginMs) << "packet " << time;
      } else if (ends) {
        EXPECT_DOUBLE_EQ(at, *ends) << "packet " << time << " does not begin where the one before ended";
      }
      ends = at + duration - skip;
    }
    offset = step["offset_ms"].get<double>();
    delay = step["delay_ms"];
  }
  EXPECT_EQ(raised, 1);
  EXPECT_EQ(kinds["late"], 1);
  EXPECT_EQ(kinds["skip"], 1);
}

}  // namespace
}  // namespace inkwire
