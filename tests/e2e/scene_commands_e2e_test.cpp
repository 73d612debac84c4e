// `inkwire-server add-scene` and `remove-scene` beside a running server (SPEC N9), end to end on
// 127.0.0.1: a scene added is taken up within a second or so and drawn by a native client; added
// again with another model, its members get the new one; a model the importer refuses is
// refused with a one-line reason, storing nothing; removed, its members are told and it is no
// longer served. Reads assimp-testmodels (skips without it).
#include <gtest/gtest.h>

#include "client/net/session_client.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/image_metrics.hpp"
#include "making_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
using namespace std::chrono_literals;

namespace {

const fs::path kModels = "/usr/share/assimp/models";
const fs::path kBox = kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf";
const fs::path kSpider = kModels / "OBJ/spider.obj";

// The server's log line of `event` for `session`, once it is there; its arrival time is when
// the test saw it.
bool logged(ServerUnderTest& server, const std::string& event, const std::string& session) { return events_for(server, event, session) > 0; }

}  // namespace

class SceneCommandsE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kBox) || !fs::exists(kSpider)) GTEST_SKIP() << kModels << " is missing (Debian package assimp-testmodels)";
  }
};

TEST_F(SceneCommandsE2ETest, AddSceneBesideARunningServerIsTakenUpReplacedAndRemoved) {
  const fs::path dir = output_dir("add-scene");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", nlohmann::json::array()}});
  const std::string data = (dir / "data").string();

  Process add("inkwire-server", {"add-scene", "teapot", "--mesh", kBox.string(), "--style", "comic", "--data", data}, dir / "add.log");
  ASSERT_EQ(add.wait(), 0) << add.output();
  const auto stored = std::chrono::steady_clock::now();
  EXPECT_NE(add.output().find("stored scene 'teapot'"), std::string::npos) << add.output();
  ASSERT_TRUE(eventually([&] { return logged(server, "session-added", "teapot"); })) << server.process().output();
  const double taken_up = std::chrono::duration<double>(std::chrono::steady_clock::now() - stored).count();
  std::printf("add-scene taken up %.2f s after it stored the scene\n", taken_up);
  EXPECT_LT(taken_up, 10.0) << "a second or so (the server looks every persist_seconds), not " << taken_up << " s";
  auto first = headless_client(server, "teapot", dir, "first", 1, 10);
  ASSERT_EQ(first->wait(), 0) << first->output();
  EXPECT_EQ(frame_log(dir / "first.jsonl").at(0)["style"], "comic");
  EXPECT_NE(http_get(http_port(server), "GET /scene/teapot HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK"), std::string::npos);

  // Added again with another model: a member in it gets the new one, the style kept.
  SessionClient member(server.address(), "member");
  const protocol::Snapshot before = member.join("teapot", "");
  Process again("inkwire-server", {"add-scene", "teapot", "--mesh", kSpider.string(), "--data", data}, dir / "again.log");
  ASSERT_EQ(again.wait(), 0) << again.output();
  ASSERT_TRUE(eventually([&] { return member.state().assets != before.assets; })) << server.process().output();
  EXPECT_EQ(member.state().assets.at(0).name, "spider.glb");
  EXPECT_EQ(member.state().style.renderer, "comic");

  // A model the importer refuses: one line, nothing stored, nothing served.
  const size_t assets = files_under(dir / "data" / "assets");
  for (const fs::path& bad : {kModels / "invalid/malformed.obj", kModels / "invalid/empty.3ds", dir / "missing.obj"}) {
    Process refused("inkwire-server", {"add-scene", "broken", "--mesh", bad.string(), "--data", data}, dir / "refused.log");
    EXPECT_NE(refused.wait(), 0) << refused.output();
    const std::string said = refused.output();
    EXPECT_EQ(said.rfind("inkwire-server add-scene: ", 0), 0u) << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << "not one line: " << said;
    EXPECT_NE(said.find(bad.filename().string()), std::string::npos) << said;
  }
  Process wrong_name("inkwire-server", {"add-scene", "a b", "--mesh", kBox.string(), "--data", data}, dir / "wrong-name.log");
  EXPECT_NE(wrong_name.wait(), 0);
  EXPECT_NE(wrong_name.output().find("must be 1-64 letters"), std::string::npos) << wrong_name.output();
  EXPECT_EQ(files_under(dir / "data" / "assets"), assets) << "a refused model left files in the store";
  // (Taking up what is stored is the same look that found teapot; one more look finds no "broken".)
  const size_t looks = log_events(server.process().output(), "session-added").size();
  Process third("inkwire-server", {"add-scene", "sentinel", "--mesh", kBox.string(), "--data", data}, dir / "sentinel.log");
  ASSERT_EQ(third.wait(), 0) << third.output();
  ASSERT_TRUE(eventually([&] { return logged(server, "session-added", "sentinel"); }));
  EXPECT_EQ(log_events(server.process().output(), "session-added").size(), looks + 1);
  EXPECT_FALSE(logged(server, "session-added", "broken"));

  // Removed: its member is told, it is no longer served, and its name is free again.
  Process remove("inkwire-server", {"remove-scene", "teapot", "--data", data}, dir / "remove.log");
  ASSERT_EQ(remove.wait(), 0) << remove.output();
  ASSERT_TRUE(eventually([&] { return !member.connected() || member.last_error().find("was removed") != std::string::npos; })) << server.process().output();
  EXPECT_NE(member.last_error().find("scene teapot was removed"), std::string::npos) << member.last_error();
  EXPECT_TRUE(logged(server, "session-removed", "teapot"));
  SessionClient late(server.address(), "late");
  EXPECT_THROW(late.join("teapot", ""), Error);
  Process twice("inkwire-server", {"remove-scene", "teapot", "--data", data}, dir / "twice.log");
  EXPECT_NE(twice.wait(), 0);
  EXPECT_NE(twice.output().find("no scene named 'teapot'"), std::string::npos) << twice.output();
  EXPECT_TRUE(server.process().running());
}
