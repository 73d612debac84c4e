// Products end to end on 127.0.0.1 (SPEC T11-T14), as a shop owner and a customer meet them:
// photos rendered like a studio's, put on the server with `inkwire-server add-product`, turned
// by headless clients. The first view comes after one photo; at a photo's own direction the
// client shows that photo; midway it is closer to the truth than the nearest photo and a
// cross-fade; once the product is there a full turn costs no bytes; a restarted server makes
// nothing again; a corrupted stored file is refused, not served; bad folders are refused with
// the file named.
#include <fstream>
#include <set>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/turntable_view.hpp"
#include "protocol/framing.hpp"
#include "common/content_hash.hpp"
#include "common/image_metrics.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

namespace {

const fs::path kDuck = "/usr/share/assimp/models/Collada/duck.dae";
constexpr int kSize = 256, kPhotos = 24;

// What a studio shoots: the object turning on a turntable in front of a white backdrop, one
// photo every 15 degrees (the view's azimuth falls as the object turns).
fs::path shoot_photos(const fs::path& dir) {
  const fs::path photos = dir / "photos";
  fs::create_directories(photos);
  Process render("inkwire-render", {"--mesh", kDuck.string(), "--style", "default", "--view", "0,0,1.4", "--frames", std::to_string(kPhotos),
                                    "--size", "256x256", "--backdrop", "#ffffff", "--out", (photos / "IMG_%04d.png").string()},
                 dir / "render.log");
  EXPECT_EQ(render.wait(), 0) << render.output();
  return photos;
}

Image render_truth(const fs::path& dir, float azimuth) {
  const fs::path out = dir / ("truth-" + std::to_string(azimuth) + ".png");
  Process render("inkwire-render", {"--mesh", kDuck.string(), "--style", "default", "--view", std::to_string(azimuth) + ",0,1.4",
                                    "--size", "256x256", "--backdrop", "#ffffff", "--out", out.string()},
                 dir / "truth.log");
  EXPECT_EQ(render.wait(), 0) << render.output();
  return load_image(out);
}

std::unique_ptr<Process> product_client(const ServerUnderTest& server, const std::string& session, const fs::path& dir,
                                        const std::string& name, int frames, const std::string& view, bool wait_for_product,
                                        const std::string& cache = "", const std::vector<std::string>& more = {}) {
  std::vector<std::string> args = {"--connect", server.address(), "--session", session, "--headless", "--frames", std::to_string(frames),
                                   "--fps", "60", "--size", "256x256", "--view", view, "--cache", (dir / (cache.empty() ? "cache-" + name : cache)).string(),
                                   "--out", (dir / (name + "-%04d.png")).string(), "--frame-log", (dir / (name + ".jsonl")).string(),
                                   "--name", name};
  if (wait_for_product) args.push_back("--wait-for-product");
  args.insert(args.end(), more.begin(), more.end());
  return std::make_unique<Process>("inkwire-client", args, dir / (name + ".log"));
}

int count_lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) n += line.rfind(prefix, 0) == 0 || line.find("] " + prefix) != std::string::npos;
  return n;
}

// The product's own photo k as the client's cache holds it: the JPEG is the photo laid on white
// already; where its matte is 0 (no object, no floor here) it shows white.
Image stored_photo(const protocol::Snapshot& state, AssetCache& cache, int k) {
  int photo = 0, matte = 0;
  Image image;
  for (const auto& a : state.assets) {
    if (a.kind == protocol::AssetKind::Samples && photo++ == k) image = load_image(cache.path_of(a));
    if (a.kind == protocol::AssetKind::Matte && matte++ == k) {
      const Image alpha = load_image(cache.path_of(a));
      for (size_t i = 0; i < image.pixels.size(); i += 4)
        if (alpha.pixels[i] == 0) image.pixels[i] = image.pixels[i + 1] = image.pixels[i + 2] = 255;
    }
  }
  return image;
}

Image blend(const Image& a, const Image& b) {
  Image out = a;
  for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = uint8_t((a.pixels[i] + b.pixels[i] + 1) / 2);
  return out;
}

}  // namespace

class TurntableE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kDuck)) GTEST_SKIP() << "needs assimp-testmodels' " << kDuck << " (run scripts/setup.sh)";
  }
};

TEST_F(TurntableE2ETest, AShopOwnersPhotosBecomeAProductACustomerTurnsWithoutABytePerInteraction) {
  const fs::path dir = output_dir("turntable-photos");
  const fs::path photos = shoot_photos(dir);
  Process add("inkwire-server", {"add-product", "duck", "--photos", photos.string(), "--step", "-15", "--data", (dir / "data").string()},
              dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  EXPECT_EQ(count_lines_starting(add.output(), "pair "), kPhotos) << add.output();  // one line per pair
  EXPECT_NE(add.output().find("stored product 'duck': 24 photos 256x256"), std::string::npos) << add.output();

  ServerUnderTest server(dir, {{"sessions", nlohmann::json::array()}});
  // A first visit: the first frame is drawn after one photo, the one nearest the view.
  auto first = product_client(server, "duck", dir, "first", 1, "0", false);
  ASSERT_EQ(first->wait(), 0) << first->output();
  const auto first_log = frame_log(dir / "first.jsonl");
  ASSERT_EQ(first_log.size(), 1u);
  EXPECT_EQ(first_log[0]["product"]["samples_loaded"], 1);
  SessionClient peek(server.address(), "peek");
  const protocol::Snapshot state = peek.join("duck", "");
  AssetCache first_cache(dir / "cache-first");
  const Image frame0 = load_image(client_frame(dir, "first", 0));
  const double own_photo_db = psnr(frame0, stored_photo(state, first_cache, 0));
  const double shot_db = psnr(frame0, load_image(photos / "IMG_0000.png"));
  std::printf("at photo 0's direction: %.2f dB against the stored photo, %.2f dB against the shot\n", own_photo_db, shot_db);
  EXPECT_GE(own_photo_db, 40.0);
  EXPECT_GE(shot_db, 33.0);  // the shot itself, through JPEG and its keyed matte

  // A customer turns it a full circle in 48 frames, once it is all there.
  auto turn = product_client(server, "duck", dir, "turn", 48, "0", true);
  ASSERT_EQ(turn->wait(), 0) << turn->output();
  const auto log = frame_log(dir / "turn.jsonl");
  ASSERT_EQ(log.size(), 48u);
  for (const auto& f : log) {
    EXPECT_EQ(f["product"]["samples_loaded"], kPhotos);
    EXPECT_EQ(f["product"]["cells_loaded"], kPhotos);
    // Not a byte either way while the view turns.
    EXPECT_EQ(f["product"]["bytes_sent"], log[0]["product"]["bytes_sent"]);
    EXPECT_EQ(f["product"]["bytes_received"], log[0]["product"]["bytes_received"]);
  }
  // Frame 47 looks from -7.5 degrees: midway between photos 0 and 1.
  const Image truth = render_truth(dir, -7.5f);
  const Image tween = load_image(client_frame(dir, "turn", 47));
  const Image photo0 = load_image(photos / "IMG_0000.png"), photo1 = load_image(photos / "IMG_0001.png");
  const double tween_db = psnr(tween, truth), nearest_db = psnr(photo0, truth), fade_db = psnr(blend(photo0, photo1), truth);
  std::printf("midway: tween %.2f dB, nearest photo %.2f dB, cross-fade %.2f dB\n", tween_db, nearest_db, fade_db);
  EXPECT_GT(tween_db, nearest_db);
  EXPECT_GT(tween_db, fade_db);

  // A second visit with the photos cached: the snapshot and the tween data, nothing more.
  auto again = product_client(server, "duck", dir, "again", 2, "90", true, "cache-turn");
  ASSERT_EQ(again->wait(), 0) << again->output();
  const auto again_log = frame_log(dir / "again.jsonl");
  ASSERT_EQ(again_log.size(), 2u);
  const uint64_t first_visit = log[0]["product"]["bytes_received"], second_visit = again_log[0]["product"]["bytes_received"];
  std::printf("bytes received: first visit %llu, with the photos cached %llu\n", (unsigned long long)first_visit,
              (unsigned long long)second_visit);
  EXPECT_LT(second_visit, first_visit / 10);
}

// The GL libraries and drivers a process has mapped (/proc/PID/maps): the off-screen and EGL
// front ends, the GL library itself and Mesa's drivers. (GLVND's dispatch stubs, libGLX.so.0 and
// libGLdispatch.so.0, are mapped by any process that links Debian's OpenCV core, which names them
// for its OpenGL interop; they load no driver until a context is made, and none is.)
std::vector<std::string> gl_mapped(pid_t pid) {
  std::ifstream maps("/proc/" + std::to_string(pid) + "/maps");
  std::set<std::string> found;
  for (std::string line; std::getline(maps, line);) {
    const std::string file = line.substr(line.find_last_of(' ') + 1);
    const std::string name = fs::path(file).filename().string();
    for (const char* gl : {"libOSMesa", "libEGL", "libGL.so", "libGLX_mesa", "_dri.so", "libgallium", "libglapi"})
      if (name.find(gl) != std::string::npos) found.insert(name);
  }
  return {found.begin(), found.end()};
}

// Issue "the house and its edges": a product made from a mesh is rendered by inkwire-mesh-product,
// a process of its own, never by the serving process, which maps no GL library after it served
// one: the product of its config at start, and one added with add-product while it runs, which is
// served under its name without a restart.
TEST_F(TurntableE2ETest, MeshProductsAreMadeOutsideTheServingProcessWhichMapsNoGLAndOneAddedWhileItRunsIsServedUntilRemoved) {
  const fs::path dir = output_dir("turntable-no-gl");
  ServerUnderTest server(dir, {{"sessions", {{{"name", "duck"}, {"kind", "turntable"},
                                              {"product", {{"mesh", kDuck.string()}, {"samples", 8}, {"size", 128}}}}}}});
  EXPECT_NE(server.process().output().find("\"product-pair\""), std::string::npos) << "no pair of the helper reached the server's log";
  auto seen = product_client(server, "duck", dir, "config", 1, "0", true);
  ASSERT_EQ(seen->wait(), 0) << seen->output();
  EXPECT_EQ(frame_log(dir / "config.jsonl").at(0)["product"]["samples_loaded"], 8);
  EXPECT_EQ(gl_mapped(server.process().pid()), std::vector<std::string>{}) << "the serving process mapped GL";

  Process add("inkwire-server", {"add-product", "cow", "--mesh", kDuck.string(), "--samples", "6", "--size", "96", "--data", (dir / "data").string()},
              dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  EXPECT_EQ(count_lines_starting(add.output(), "pair "), 6) << add.output();
  EXPECT_TRUE(eventually([&] { return server.process().output().find("\"session\":\"cow\"") != std::string::npos; }))
      << "the running server did not take up the product added beside it";
  auto cow = product_client(server, "cow", dir, "added", 1, "0", true);
  ASSERT_EQ(cow->wait(), 0) << cow->output();
  EXPECT_EQ(frame_log(dir / "added.jsonl").at(0)["product"]["samples_loaded"], 6);
  EXPECT_EQ(gl_mapped(server.process().pid()), std::vector<std::string>{}) << "the serving process mapped GL";

  // Taken out again while the server runs: no longer served; a name never stored is refused.
  Process remove("inkwire-server", {"remove-product", "cow", "--data", (dir / "data").string()}, dir / "remove.log");
  ASSERT_EQ(remove.wait(), 0) << remove.output();
  EXPECT_TRUE(eventually([&] { return server.process().output().find("\"product-removed\"") != std::string::npos; }))
      << "the running server did not drop the product removed beside it";
  auto gone = product_client(server, "cow", dir, "removed", 1, "0", true);
  EXPECT_NE(gone->wait(), 0) << gone->output();
  Process again("inkwire-server", {"remove-product", "cow", "--data", (dir / "data").string()}, dir / "remove-again.log");
  EXPECT_NE(again.wait(), 0);
  EXPECT_NE(again.output().find("no product named 'cow'"), std::string::npos) << again.output();
  auto duck = product_client(server, "duck", dir, "still", 1, "0", true);
  EXPECT_EQ(duck->wait(), 0) << duck->output();
}

TEST_F(TurntableE2ETest, RowsOfPhotosTurnUpAndDownAClientTurnedUpSeesTheUpperRow) {
  // A studio's three rows (SPEC T17): 12 photos at each of three camera heights, a folder a row.
  const fs::path dir = output_dir("turntable-rows");
  const std::vector<int> elevations = {0, 25, 50};
  for (size_t r = 0; r < elevations.size(); ++r) {
    const fs::path row = dir / "photos" / ("row" + std::to_string(r + 1));
    fs::create_directories(row);
    Process render("inkwire-render", {"--mesh", kDuck.string(), "--style", "default", "--view", "0," + std::to_string(elevations[r]) + ",1.4",
                                      "--frames", "12", "--size", "256x256", "--backdrop", "#ffffff", "--out", (row / "IMG_%04d.png").string()},
                   dir / "render.log");
    ASSERT_EQ(render.wait(), 0) << render.output();
  }
  Process add("inkwire-server", {"add-product", "duck", "--photos", (dir / "photos").string(), "--step", "-30", "--elevations", "0,25,50",
                                 "--data", (dir / "data").string()},
              dir / "add.log");
  // Finding the shape of 36 photos takes half a minute alone on this machine's two cores, and
  // several minutes when they are busy with other work (ctest gives this test 600 s).
  ASSERT_EQ(add.wait(std::chrono::seconds(540)), 0) << add.output();
  EXPECT_EQ(count_lines_starting(add.output(), "pair "), 2 * 2 * 12) << add.output();  // two triangles a quad
  EXPECT_NE(add.output().find("shape from the mattes"), std::string::npos) << add.output();
  EXPECT_NE(add.output().find("stored product 'duck': 36 photos 256x256"), std::string::npos) << add.output();

  ServerUnderTest server(dir, {{"sessions", nlohmann::json::array()}});
  // Turned up to the top row, the client shows the top row's photo, not the bottom one's.
  auto up = product_client(server, "duck", dir, "up", 1, "0,50", true);
  ASSERT_EQ(up->wait(), 0) << up->output();
  const Image top = load_image(client_frame(dir, "up", 0));
  const double top_db = psnr(top, load_image(dir / "photos" / "row3" / "IMG_0000.png"));
  const double bottom_db = psnr(top, load_image(dir / "photos" / "row1" / "IMG_0000.png"));
  std::printf("turned up to 50 degrees: %.2f dB against the top row's photo, %.2f dB against the bottom row's\n", top_db, bottom_db);
  EXPECT_GE(top_db, 33.0);
  EXPECT_GT(top_db, bottom_db + 6.0);
  // Between four photos (15 degrees round, 12.5 up): closer to the truth than the nearest photo.
  auto between = product_client(server, "duck", dir, "between", 1, "-15,12.5", true);
  ASSERT_EQ(between->wait(), 0) << between->output();
  const fs::path truth_file = dir / "truth-between.png";
  Process render("inkwire-render", {"--mesh", kDuck.string(), "--style", "default", "--view", "-15,12.5,1.4", "--size", "256x256",
                                    "--backdrop", "#ffffff", "--out", truth_file.string()},
                 dir / "truth.log");
  ASSERT_EQ(render.wait(), 0) << render.output();
  const Image truth = load_image(truth_file), view = load_image(client_frame(dir, "between", 0));
  double nearest_db = 0;
  for (const char* photo : {"row1/IMG_0000.png", "row1/IMG_0001.png", "row2/IMG_0000.png", "row2/IMG_0001.png"})
    nearest_db = std::max(nearest_db, psnr(load_image(dir / "photos" / photo), truth));
  const double tween_db = psnr(view, truth);
  std::printf("between two rows and two photos: tween %.2f dB, the best of the four photos %.2f dB\n", tween_db, nearest_db);
  EXPECT_GT(tween_db, nearest_db + 1.0);
}

TEST_F(TurntableE2ETest, LargePhotosAreFetchedAtAFinerLevelOnlyWhenZoomedInAndShowTheirDetail) {
  // A studio's photos at 1024 pixels (SPEC T18): kept as a zoom level above the 512-pixel first one.
  const fs::path dir = output_dir("turntable-zoom");
  const fs::path photos = dir / "photos";
  fs::create_directories(photos);
  Process render("inkwire-render", {"--mesh", kDuck.string(), "--style", "default", "--view", "0,0,1.4", "--frames", "12",
                                    "--size", "1024x1024", "--backdrop", "#ffffff", "--out", (photos / "IMG_%04d.png").string()},
                 dir / "render.log");
  ASSERT_EQ(render.wait(), 0) << render.output();
  Process add("inkwire-server", {"add-product", "duck", "--photos", photos.string(), "--step", "-30", "--data", (dir / "data").string()},
              dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  EXPECT_NE(add.output().find("12 photos 512x512"), std::string::npos) << add.output();
  EXPECT_NE(add.output().find("zoom level 1024x1024"), std::string::npos) << add.output();

  ServerUnderTest server(dir, {{"sessions", nlohmann::json::array()}});
  SessionClient peek(server.address(), "peek");
  const protocol::Snapshot state = peek.join("duck", "");
  ASSERT_EQ(state.product.levels, (std::vector<protocol::ImageSize>{{1024, 1024}}));
  std::vector<protocol::AssetAnnounce> zoom_photos;
  for (const auto& a : state.assets)
    if (a.kind == protocol::AssetKind::Zoom) zoom_photos.push_back(a);
  ASSERT_EQ(zoom_photos.size(), 12u);
  auto fetched_zoom_photos = [&](const std::string& cache) {
    AssetCache held(dir / cache);
    return std::count_if(zoom_photos.begin(), zoom_photos.end(), [&](const auto& a) { return held.has(a); });
  };
  auto last_log = [&](const std::string& name) {
    std::ifstream in(dir / (name + ".jsonl"));
    nlohmann::json line;
    for (std::string text; std::getline(in, text);) line = nlohmann::json::parse(text)["product"];
    return line;
  };

  // Not zoomed in (256 pixels shows the 512-pixel photos at half their size; zoomed twice, at
  // theirs): every first-level photo, no finer one.
  for (const std::string zoom : {"1", "2"}) {
    auto client = product_client(server, "duck", dir, "zoom" + zoom, 1, "0,0," + zoom, true);
    ASSERT_EQ(client->wait(), 0) << client->output();
    EXPECT_EQ(last_log("zoom" + zoom)["samples_loaded"], 12);
    EXPECT_EQ(last_log("zoom" + zoom)["finer_loaded"], 0);
    EXPECT_EQ(fetched_zoom_photos("cache-zoom" + zoom), 0) << "zoom " << zoom;
  }
  // Zoomed in four times: the photo is shown at 1024 pixels, the finer level of the photos the
  // view is drawn from is fetched (then of those nearest it, up to kFinerKept, while the client
  // runs), and the view shows the detail the photo has.
  auto zoomed = product_client(server, "duck", dir, "zoom4", 1, "0,0,4", true);
  ASSERT_EQ(zoomed->wait(), 0) << zoomed->output();
  EXPECT_GE(last_log("zoom4")["finer_in_view"], 1);
  const auto fetched = fetched_zoom_photos("cache-zoom4");
  EXPECT_GE(fetched, 1);
  EXPECT_LE(fetched, kFinerKept);
  // What the 256-pixel window shows: the middle of the photo at 1024 pixels.
  const Image truth = cropped(load_image(photos / "IMG_0000.png"), 384, 384, 256, 256);
  const Image view = load_image(client_frame(dir, "zoom4", 0));
  AssetCache held(dir / "cache-zoom4");
  const Image first_level = resized(cropped(stored_photo(state, held, 0), 192, 192, 128, 128), 256, 256);
  const double zoomed_db = psnr(view, truth), first_db = psnr(first_level, truth);
  std::printf("zoomed in 4 times: %.2f dB against the photo; the first level scaled up %.2f dB; %ld of 12 finer photos fetched\n",
              zoomed_db, first_db, long(fetched));
  EXPECT_GT(zoomed_db, first_db + 2.0);
}

TEST_F(TurntableE2ETest, ARestartedServerMakesNothingAgainAndACorruptedFileIsRefusedNotServed) {
  const fs::path dir = output_dir("turntable-restart");
  const std::vector<std::string> add_args = {"add-product", "duck", "--mesh", kDuck.string(), "--samples", "12", "--size", "128",
                                             "--data", (dir / "data").string()};
  Process add("inkwire-server", add_args, dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  EXPECT_EQ(count_lines_starting(add.output(), "pair "), 12) << add.output();
  Process add_again("inkwire-server", add_args, dir / "add-again.log");
  ASSERT_EQ(add_again.wait(), 0) << add_again.output();
  EXPECT_EQ(count_lines_starting(add_again.output(), "pair "), 0) << add_again.output();
  EXPECT_NE(add_again.output().find("already stored"), std::string::npos) << add_again.output();

  const nlohmann::json config = {{"sessions", {{{"name", "scene"}, {"kind", "scene"}, {"assets", nlohmann::json::array()}}}}};
  ServerUnderTest server(dir, config);
  for (int start = 0; start < 2; ++start) {
    if (start > 0) server.kill(), server.start();
    EXPECT_EQ(log_events(server.process().output(), "product-made").size(), 0u) << server.process().output();
    EXPECT_EQ(log_events(server.process().output(), "product-loaded").size(), 1u) << server.process().output();
    auto client = product_client(server, "duck", dir, "visit-" + std::to_string(start), 1, "30", true);
    EXPECT_EQ(client->wait(), 0) << client->output();
  }

  // One byte of the stored tween data changes on disk: found at start by its hash and refused
  // with the reason; the other sessions are served as ever.
  SessionClient peek(server.address(), "peek");
  const protocol::Snapshot state = peek.join("duck", "");
  for (const auto& a : state.assets)
    if (a.kind == protocol::AssetKind::Tween) {
      std::fstream file(dir / "data" / "assets" / to_hex(a.hash), std::ios::in | std::ios::out | std::ios::binary);
      file.seekp(12);
      file.put('\x55');
    }
  server.kill();
  server.start();
  const auto unavailable = log_events(server.process().output(), "product-unavailable");
  ASSERT_EQ(unavailable.size(), 1u) << server.process().output();
  EXPECT_NE(unavailable[0]["reason"].get<std::string>().find("does not match its hash"), std::string::npos);
  auto refused = product_client(server, "duck", dir, "refused", 1, "0", true);
  EXPECT_NE(refused->wait(), 0);
  EXPECT_NE(refused->output().find("cannot be shown"), std::string::npos) << refused->output();
  SessionClient other(server.address(), "other");
  EXPECT_NO_THROW(other.join("scene", ""));
}

TEST(TurntableOrbitTest, AViewSharedAsAPoseComesBackAsTheSameView) {
  for (const TurntableOrbit view : {TurntableOrbit{}, TurntableOrbit{.azimuth = 30, .elevation = 0, .zoom = 1.5f},
                                    TurntableOrbit{.azimuth = -170, .elevation = 40, .zoom = 0.5f},
                                    TurntableOrbit{.azimuth = 95, .elevation = -80, .zoom = 1}}) {
    const protocol::ObjectPose pose = view.pose(7);
    EXPECT_NEAR(glm::length(pose.rotation), 1.0f, 1e-6f);
    // No roll: the product's vertical stays upright on screen (in the camera's y-z plane).
    const glm::quat turn(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
    EXPECT_NEAR((turn * glm::vec3(0, 1, 0)).x, 0.0f, 1e-6f);
    const TurntableOrbit back = TurntableOrbit::from_pose(pose);
    EXPECT_NEAR(back.azimuth, view.azimuth, 1e-3f);
    EXPECT_NEAR(back.elevation, view.elevation, 1e-3f);
    EXPECT_FLOAT_EQ(back.zoom, view.zoom);
    // What survives the wire survives too.
    const protocol::Bytes frame = protocol::encode(pose);
    const auto decoded = std::get<protocol::ObjectPose>(protocol::decode_frame(frame.data(), frame.size()));
    EXPECT_NEAR(TurntableOrbit::from_pose(decoded).azimuth, view.azimuth, 1e-3f);
  }
  // The web client's quaternion for the same view (client/web/test/turntable_pose.test.js).
  const glm::vec4 rotation = TurntableOrbit{.azimuth = 30, .elevation = 20, .zoom = 1.5f}.pose(1).rotation;
  const glm::vec4 web(0.167731f, -0.254887f, -0.044943f, 0.951251f);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(rotation[i], web[i], 1e-6f) << i;
}

TEST_F(TurntableE2ETest, FollowersShowTheEditorsViewAVisitorWhoTriesToPresentIsRefusedAndOthersKeepTheirOwn) {
  const fs::path dir = output_dir("turntable-presenter");
  Process add("inkwire-server", {"add-product", "duck", "--mesh", kDuck.string(), "--samples", "12", "--size", "128", "--data",
                                 (dir / "data").string(), "--editor-token", "sh0p-0wner"},
              dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  ServerUnderTest server(dir, {{"sessions", nlohmann::json::array()}});
  const auto client = [&](const std::string& name, int frames, const std::string& view, const std::string& mode) {
    std::vector<std::string> more = mode.empty() ? std::vector<std::string>{} : std::vector{mode};
    if (name == "presenter") more.insert(more.end(), {"--token", "sh0p-0wner"});
    return product_client(server, "duck", dir, name, frames, view, true, "", more);
  };
  // A follower and a visitor of their own are there (3 s at 60 frames a second) while the
  // presenter turns the product from 30 degrees, 9 degrees a frame.
  auto follower = client("follower", 180, "0", "--follow");
  auto visitor = client("visitor", 180, "200", "");
  ASSERT_TRUE(eventually([&] { return !frame_log(dir / "follower.jsonl").empty() && !frame_log(dir / "visitor.jsonl").empty(); }))
      << follower->output() << visitor->output();
  // A visitor without the editor token tries to present first: refused, with the reason shown.
  auto stranger = client("stranger", 20, "120", "--present");
  ASSERT_EQ(stranger->wait(), 0) << stranger->output();
  const auto strange = frame_log(dir / "stranger.jsonl");
  ASSERT_FALSE(strange.empty());
  ASSERT_TRUE(strange.back().contains("refused")) << strange.back().dump();
  EXPECT_NE(strange.back()["refused"]["reason"].get<std::string>().find("only the product's editor"), std::string::npos);
  auto presenter = client("presenter", 40, "30", "--present");
  ASSERT_EQ(presenter->wait(), 0) << presenter->output();
  ASSERT_EQ(follower->wait(), 0) << follower->output();
  ASSERT_EQ(visitor->wait(), 0) << visitor->output();
  const auto presented = frame_log(dir / "presenter.jsonl");
  ASSERT_EQ(presented.size(), 40u);
  EXPECT_GT(presented.back()["product"]["bytes_sent"].get<uint64_t>(), presented.front()["product"]["bytes_sent"].get<uint64_t>());
  // The follower shows no view the editor did not present (the first sample's before any came):
  // none of the stranger's 120-degree turn reached it.
  const auto on_the_circle = [](double degrees) { return std::remainder(degrees, 360.0); };
  const auto was_presented = [&](double azimuth) {
    for (const auto& f : presented)
      if (std::abs(on_the_circle(f["product"]["azimuth"].get<double>() - azimuth)) < 0.01) return true;
    return std::abs(on_the_circle(azimuth)) < 0.01;
  };
  const auto followed = frame_log(dir / "follower.jsonl");
  for (const auto& f : followed) EXPECT_TRUE(was_presented(f["product"]["azimuth"].get<double>())) << f.dump();
  // The visitor's own turn, untouched: 200 degrees and 2 degrees a frame, sending nothing but
  // its answers to the server's heartbeat (a pong is 14 bytes: the 6-byte header and the nonce;
  // on a loaded machine its 3 s last past a heartbeat).
  const auto own = frame_log(dir / "visitor.jsonl");
  for (size_t i = 0; i < own.size(); ++i) {
    EXPECT_NEAR(on_the_circle(own[i]["product"]["azimuth"].get<double>() - (200.0 + 2.0 * double(i))), 0.0, 0.01);
    EXPECT_EQ((own[i]["product"]["bytes_sent"].get<uint64_t>() - own[0]["product"]["bytes_sent"].get<uint64_t>()) % 14, 0u) << own[i].dump();
  }

  // One who follows later joins at the presenter's last view (the session keeps it) and shows
  // what the presenter showed there.
  auto late = client("late", 2, "0", "--follow");
  ASSERT_EQ(late->wait(), 0) << late->output();
  const auto late_log = frame_log(dir / "late.jsonl");
  ASSERT_EQ(late_log.size(), 2u);
  EXPECT_NEAR(on_the_circle(late_log[1]["product"]["azimuth"].get<double>() - presented.back()["product"]["azimuth"].get<double>()), 0.0, 0.01);
  const double db = psnr(load_image(client_frame(dir, "late", 1)), load_image(client_frame(dir, "presenter", 39)));
  std::printf("a late follower's view against the presenter's last: %.2f dB\n", db);
  EXPECT_GE(db, 40.0);
}

TEST_F(TurntableE2ETest, BadPhotoFoldersAreRefusedWithTheFileNamedAndNothingStored) {
  const fs::path dir = output_dir("turntable-refusals");
  const fs::path photos = shoot_photos(dir);
  auto refuse = [&](const std::string& name, std::vector<std::string> args, const std::string& reason) {
    SCOPED_TRACE(name);
    args.insert(args.begin(), {"add-product", name});
    args.insert(args.end(), {"--data", (dir / "data").string()});
    Process add("inkwire-server", args, dir / (name + ".log"));
    EXPECT_NE(add.wait(), 0);
    const std::string out = add.output();
    EXPECT_NE(out.find(reason), std::string::npos) << out;
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 1) << "one line: " << out;
  };
  auto folder = [&](const std::string& name, int photo_count) {
    const fs::path f = dir / name;
    fs::create_directories(f);
    for (int i = 0; i < photo_count; ++i) fs::copy_file(photos / ("IMG_000" + std::to_string(i) + ".png"), f / ("IMG_000" + std::to_string(i) + ".png"));
    return f;
  };
  refuse("missing", {"--photos", (dir / "nowhere").string()}, "is not a folder");
  refuse("empty", {"--photos", folder("empty", 0).string()}, "holds 0 photos; a turntable needs at least 3");
  refuse("two", {"--photos", folder("two", 2).string()}, "holds 2 photos; a turntable needs at least 3");
  const fs::path other = folder("other", 5);
  std::ofstream(other / "invoice.pdf") << "%PDF";
  refuse("other", {"--photos", other.string()}, "invoice.pdf is not a photo");
  const fs::path broken = folder("broken", 5);
  std::ofstream(broken / "IMG_0003.png", std::ios::trunc) << "not a png";
  refuse("broken", {"--photos", broken.string()}, "IMG_0003.png cannot be read");
  const fs::path mixed = folder("mixed", 5);
  Process portrait("inkwire-render", {"--mesh", kDuck.string(), "--size", "128x256", "--out", (mixed / "IMG_0004.png").string()}, dir / "portrait.log");
  ASSERT_EQ(portrait.wait(), 0);
  refuse("mixed", {"--photos", mixed.string()}, "IMG_0004.png is 128x256, not the shape of the first photo");
  refuse("badmesh", {"--mesh", "/usr/share/assimp/models/invalid/empty.obj"}, "add-product:");
  refuse("bad name!", {"--photos", photos.string()}, "must be 1-64 letters");
  EXPECT_FALSE(fs::exists(dir / "data" / "assets") && !fs::is_empty(dir / "data" / "assets"));
}
