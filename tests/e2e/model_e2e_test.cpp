// Whole models over the network and honest exits, end to end on 127.0.0.1: a glTF of three
// files (the .gltf, its .bin and its texture) put in a session reaches a headless client whole
// and draws as inkwire-render draws the file itself; a client that cannot load what it has
// exits non-zero; the server refuses a model it cannot read, and a busy port before it creates
// anything on disk. Reads assimp-testmodels' CesiumMilkTruck (skips without it).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "common/image.hpp"
#include "common/image_metrics.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
namespace fs = std::filesystem;

namespace {

const fs::path kTruck = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";

nlohmann::json truck_config(const fs::path& model) {
  return {{"sessions", {{{"name", "truck"}, {"kind", "scene"}, {"style", "default"}, {"assets", {{{"path", model.string()}, {"kind", "mesh"}}}}}}}};
}

// A server that should refuse to start: its exit code and what it said.
std::pair<int, std::string> refused_server(const fs::path& dir, const std::vector<std::string>& args) {
  Process server("inkwire-server", args, dir / "refused.log");
  const int code = server.wait(std::chrono::seconds(60));
  return {code, server.output()};
}

}  // namespace

class ModelE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kTruck)) GTEST_SKIP() << kTruck << " is missing (Debian package assimp-testmodels)";
  }
};

TEST_F(ModelE2ETest, AGltfOfThreeFilesReachesTheClientWholeAndDrawsAsTheFileDoes) {
  const fs::path dir = output_dir("model-whole");
  ServerUnderTest server(dir, truck_config(kTruck));
  auto client = headless_client(server, "truck", dir, "viewer", 1, 10);
  ASSERT_EQ(client->wait(), 0) << client->output();
  // The server made it one file: the client's cache holds a single GLB, no .gltf.
  std::vector<fs::path> cached;
  for (const auto& e : fs::directory_iterator(dir / "cache-viewer")) cached.push_back(e.path());
  ASSERT_EQ(cached.size(), 1u);
  EXPECT_EQ(cached[0].extension(), ".glb");

  // The session's camera (orbit 30, 20 at 1.4 diagonals) and style, drawn from the file.
  Process render("inkwire-render", {"--mesh", kTruck.string(), "--view", "30,20,1.4", "--size", "240x180", "--out", (dir / "render.png").string()},
                 dir / "render.log");
  ASSERT_EQ(render.wait(), 0) << render.output();
  const Image from_session = load_image(client_frame(dir, "viewer", 0)), from_file = load_image(dir / "render.png");
  const double db = psnr(from_session, from_file);
  EXPECT_GE(db, 40.0) << "the client's truck differs from the file's (texture or colours lost on the way?)";
  // Not a blank picture either: the texture's blue and green are there.
  int coloured = 0;
  for (size_t i = 0; i < from_session.pixels.size(); i += 4) {
    const int r = from_session.pixels[i], g = from_session.pixels[i + 1], b = from_session.pixels[i + 2];
    coloured += std::max({r, g, b}) - std::min({r, g, b}) > 60;
  }
  EXPECT_GT(coloured, 100) << "no textured pixels";
}

TEST_F(ModelE2ETest, AClientThatCannotLoadTheModelItHasExitsNonZeroSayingWhy) {
  const fs::path dir = output_dir("model-unloadable");
  ServerUnderTest server(dir, truck_config(kTruck));
  auto first = headless_client(server, "truck", dir, "viewer", 1, 10);
  ASSERT_EQ(first->wait(), 0) << first->output();
  // The cached model damaged on disk, its size kept (the cache trusts a complete file).
  for (const auto& e : fs::directory_iterator(dir / "cache-viewer")) {
    const auto size = fs::file_size(e.path());
    std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << std::string(size, '\0');
  }
  auto second = headless_client(server, "truck", dir, "viewer", 1, 10);
  EXPECT_NE(second->wait(), 0) << second->output();
  EXPECT_NE(second->output().find("cannot load the session's mesh"), std::string::npos) << second->output();
}

TEST_F(ModelE2ETest, TheServerRefusesAModelItCannotReadOrAFolderNamingThePath) {
  const fs::path dir = output_dir("model-refused");
  fs::create_directories(dir / "a-folder");
  std::ofstream(dir / "broken.obj") << "v 0 0\nf 1 2 9\n";
  for (const fs::path& model : {dir / "a-folder", dir / "broken.obj", dir / "missing.gltf"}) {
    std::ofstream(dir / "refused.json") << truck_config(model).dump();
    const auto [code, said] = refused_server(dir, {"--listen", "127.0.0.1:0", "--data", (dir / "data").string(), "--config", (dir / "refused.json").string()});
    EXPECT_NE(code, 0) << said;
    EXPECT_NE(said.find(model.string()), std::string::npos) << "the refusal names the file: " << said;
    EXPECT_NE(said.find("inkwire-server: "), std::string::npos) << said;
  }
}

TEST_F(ModelE2ETest, ABusyPortFailsBeforeAnythingIsCreatedOnDisk) {
  const fs::path dir = output_dir("busy-port");
  ServerUnderTest first(dir, {{"sessions", nlohmann::json::array()}});
  const auto [code, said] = refused_server(dir, {"--listen", first.address(), "--data", (dir / "second-data").string()});
  EXPECT_NE(code, 0) << said;
  EXPECT_NE(said.find("cannot listen on " + first.address()), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(dir / "second-data")) << "the refused server created its data folder";
}

// glmark2's horse.3ds was modelled Y-up, though 3D Studio files are Z-up by convention (and
// assimp turns them so): drawn as the format says it lies on its side; told its file's Y is up
// it stands, its height along the screen's vertical.
TEST(ModelUpAxisTest, TheHorseStandsWhenToldWhichOfItsAxesIsUp) {
  const fs::path horse = "/usr/share/glmark2/models/horse.3ds";
  if (!fs::exists(horse)) GTEST_SKIP() << horse << " is missing (Debian package glmark2-data)";
  const fs::path dir = output_dir("up-axis");
  // The object's extent on screen: the box of pixels that are not the backdrop's colour.
  const auto extent = [&](const std::string& up) {
    const fs::path out = dir / ("horse-up-" + up + ".png");
    Process render("inkwire-render", {"--mesh", horse.string(), "--up", up, "--view", "0,0", "--size", "200x200", "--out", out.string()}, dir / "render.log");
    EXPECT_EQ(render.wait(), 0) << render.output();
    const Image image = load_image(out);
    int x0 = image.width, y0 = image.height, x1 = -1, y1 = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
        if (std::abs(p[0] - image.pixels[0]) + std::abs(p[1] - image.pixels[1]) + std::abs(p[2] - image.pixels[2]) < 12) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    return std::pair{x1 - x0 + 1, y1 - y0 + 1};
  };
  const auto [lying_w, lying_h] = extent("auto");
  const auto [standing_w, standing_h] = extent("y");
  EXPECT_GT(lying_w, lying_h) << "as the format says, the horse lies along the screen's horizontal";
  EXPECT_GT(standing_h, 1.2 * standing_w) << "told its Y is up, the horse's height is the screen's vertical";
}
