// End to end on 127.0.0.1 (SPEC N1-N5): a real inkwire-server, real headless inkwire-client
// processes, and an in-process SessionClient acting as the user who changes things.
#include <asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"
#include "common/image.hpp"
#include "common/model_bundle.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
namespace fs = std::filesystem;

namespace {

const fs::path kMesh = fs::path(INKWIRE_MESH_DIR) / "cow.off";

// A scene session "cows" and a session "locked" with a token.
nlohmann::json cows_config() {
  return {{"sessions", {{{"name", "cows"}, {"kind", "scene"}, {"style", "default"}, {"assets", {{{"path", kMesh.string()}}}}},
                        {{"name", "locked"}, {"kind", "scene"}, {"token", "s3cret"}, {"assets", nlohmann::json::array()}}}}};
}

// The same state drawn by this process, for comparison with what a client wrote.
Image render_locally(const protocol::Snapshot& state, const std::vector<fs::path>& files, glm::ivec2 size) {
  auto context = create_offscreen_context(size.x, size.y);
  Canvas canvas(size.x, size.y, 4);
  SessionView view;
  view.update(state, files);
  canvas.bind();
  view.draw(size, 0.0, 0);
  return canvas.read();
}

}  // namespace

class SessionE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  }
};

TEST_F(SessionE2ETest, ThreeClientsFollowOneChangeWithinTwoFramesAndALateJoinerGetsTheSnapshot) {
  const fs::path dir = output_dir("three-clients");
  ServerUnderTest server(dir, cows_config());
  const int frames = 30, fps = 10;
  auto b = headless_client(server, "cows", dir, "b", frames, fps);
  auto c = headless_client(server, "cows", dir, "c", frames, fps);
  // Change once both are drawing.
  ASSERT_TRUE(eventually([&] { return frame_log(dir / "b.jsonl").size() >= 3 && frame_log(dir / "c.jsonl").size() >= 3; }))
      << b->output() << c->output();

  SessionClient a(server.address(), "a");
  a.join("cows", "");
  AssetCache cache(dir / "cache-a");
  const int64_t sent_us = monotonic_us();
  a.send(protocol::StyleChange{.renderer = "comic", .settings = {"shade_map=two-tone"}});
  a.send(orbit_pose(120, 30, 1.3f, 1));
  const protocol::Snapshot changed = a.state();
  ASSERT_EQ(b->wait(), 0) << b->output();
  ASSERT_EQ(c->wait(), 0) << c->output();

  const Image expected = render_locally(changed, a.fetch_assets(changed, cache), {240, 180});
  for (const std::string name : {"b", "c"}) {
    SCOPED_TRACE(name);
    const auto log = frame_log(dir / (name + ".jsonl"));
    ASSERT_EQ(log.size(), size_t(frames));
    // Frames drawn after the change was sent that still show the old state: at most the one in
    // progress and the next.
    int stale = 0;
    for (const auto& f : log)
      if (f["monotonic_us"].get<int64_t>() > sent_us && f["revision"].get<uint32_t>() < changed.revision) ++stale;
    EXPECT_LE(stale, 2);
    EXPECT_EQ(log.back()["revision"].get<uint32_t>(), changed.revision);
    EXPECT_EQ(log.back()["style"].get<std::string>(), "comic shade_map=two-tone");
    const Image last = load_image(client_frame(dir, name, frames - 1));
    EXPECT_LT(mean_difference(last, expected), 0.5) << "the client's last frame differs from the same state drawn here";
  }

  // A late joiner draws the changed state from its very first frame.
  auto d = headless_client(server, "cows", dir, "d", 1, 10);
  ASSERT_EQ(d->wait(), 0) << d->output();
  EXPECT_EQ(frame_log(dir / "d.jsonl").at(0)["revision"].get<uint32_t>(), changed.revision);
  EXPECT_LT(mean_difference(load_image(client_frame(dir, "d", 0)), expected), 0.5);
}

TEST_F(SessionE2ETest, AClientThatStopsReadingDoesNotDelayTheOthers) {
  const fs::path dir = output_dir("slow-reader");
  ServerUnderTest server(dir, cows_config());
  // The slow client: says hello, joins, then never reads a byte.
  asio::io_context io;
  asio::ip::tcp::socket slow(io);
  slow.connect(server.endpoint());
  for (const protocol::Message& m : {protocol::Message(protocol::Hello{.client_name = "slow"}), protocol::Message(protocol::Join{.session = "cows", .token = ""})}) {
    const auto frame = protocol::encode(m);
    asio::write(slow, asio::buffer(frame));
  }
  SessionClient a(server.address(), "a"), b(server.address(), "b");
  a.join("cows", "");
  b.join("cows", "");
  ASSERT_TRUE(eventually([&] {
    for (const auto& j : log_events(server.process().output(), "join"))
      if (j.value("name", "") == "slow" && j.value("session", "") == "cows") return true;
    return false;
  }));
  // About 12 MB of style changes (far more than the socket buffers hold) and a pose after each.
  protocol::StyleChange big{.renderer = "comic", .settings = {}};
  for (int i = 0; i < 60; ++i) big.settings.push_back("k" + std::to_string(i) + "=" + std::string(200, 'x'));
  const int changes = 1000;
  for (int i = 1; i <= changes; ++i) {
    a.send(big);
    a.send(orbit_pose(float(i % 360), 10, 1.4f, uint32_t(i)));
  }
  // The reading client sees the very last pose; the server is still answering newcomers.
  EXPECT_TRUE(eventually([&] { return b.state().camera.sequence == uint32_t(changes); }, std::chrono::seconds(30)))
      << "b is at pose " << b.state().camera.sequence;
  SessionClient late(server.address(), "late");
  EXPECT_EQ(late.join("cows", "").camera.sequence, uint32_t(changes));
  EXPECT_TRUE(server.process().running());
}

TEST_F(SessionE2ETest, WrongTokenBadVersionAndGarbageAreRefusedWithReasonsWhileOthersAreServed) {
  const fs::path dir = output_dir("refusals");
  ServerUnderTest server(dir, cows_config());
  SessionClient good(server.address(), "good");
  good.join("cows", "");

  SessionClient wrong(server.address(), "wrong");
  try {
    wrong.join("locked", "guess");
    ADD_FAILURE() << "a wrong token was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wrong token"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(wrong.join("locked", "s3cret"));

  // Raw peers: a future version, then bytes that are no protocol at all.
  auto answer_to = [&](const protocol::Bytes& bytes) {
    asio::io_context io;
    asio::ip::tcp::socket s(io);
    s.connect(server.endpoint());
    asio::write(s, asio::buffer(bytes));
    protocol::FrameDecoder decoder;
    std::array<uint8_t, 4096> buffer{};
    std::error_code ec;
    for (;;) {
      const size_t n = s.read_some(asio::buffer(buffer), ec);
      if (ec) return protocol::Message(protocol::Leave{});  // closed without an answer
      decoder.feed(buffer.data(), n);
      if (auto m = decoder.next()) return *m;
    }
  };
  const auto version_reply = answer_to(protocol::encode(protocol::Hello{.magic = protocol::kMagic, .version = 99, .client_name = "future"}));
  ASSERT_TRUE(std::holds_alternative<protocol::ErrorMessage>(version_reply));
  EXPECT_EQ(std::get<protocol::ErrorMessage>(version_reply).code, protocol::ErrorCode::BadVersion);
  EXPECT_NE(std::get<protocol::ErrorMessage>(version_reply).reason.find("version " + std::to_string(protocol::kVersion)), std::string::npos);
  const auto garbage_reply = answer_to(protocol::Bytes{'G', 'E', 'T', ' ', '/', ' ', 'H', 'T', 'T', 'P', '/', '1', '.', '1', '\r', '\n'});
  ASSERT_TRUE(std::holds_alternative<protocol::ErrorMessage>(garbage_reply));
  EXPECT_EQ(std::get<protocol::ErrorMessage>(garbage_reply).code, protocol::ErrorCode::Malformed);

  // The well-behaved client was never disturbed.
  good.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  SessionClient observer(server.address(), "observer");
  EXPECT_EQ(observer.join("cows", "").style.renderer, "hatching");
  EXPECT_TRUE(good.connected());
}

TEST_F(SessionE2ETest, AKilledServerRestartsWithItsCatalogueAndAssetsIntact) {
  const fs::path dir = output_dir("restart");
  ServerUnderTest server(dir, cows_config());
  {
    SessionClient a(server.address(), "a");
    a.join("cows", "");
    a.send(protocol::StyleChange{.renderer = "sketch-pencil", .settings = {"seed=7"}});
    // The server persists style changes at once; wait for it to have seen this one.
    SessionClient check(server.address(), "check");
    ASSERT_TRUE(eventually([&] { return check.join("cows", "").style.renderer == "sketch-pencil"; }));
  }
  server.kill();
  server.start();
  SessionClient after(server.address(), "after");
  const protocol::Snapshot state = after.join("cows", "");
  EXPECT_EQ(state.style.renderer, "sketch-pencil");
  EXPECT_EQ(state.style.settings, std::vector<std::string>{"seed=7"});
  ASSERT_EQ(state.assets.size(), 1u);
  AssetCache fresh(dir / "cache-after");
  const auto files = after.fetch_assets(state, fresh);  // verifies the SHA-256 of what arrives
  // The mesh as the server made it whole (an OFF travels as one GLB), byte for byte.
  EXPECT_EQ(fs::file_size(files.at(0)), self_contained_model(kMesh)->bytes.size());
}

// Authority on the server (SPEC W8): a scene that names an editor token takes style, camera and
// pose changes from editors only. A visitor's change is refused with the reason, the visitor's
// copy goes back to the session's value and nobody else sees the change; the editor's reaches
// everyone. A wrong editor token on an open session is a wrong token.
TEST_F(SessionE2ETest, AVisitorsChangeIsRefusedWithTheReasonWhileTheEditorsReachesEveryone) {
  const fs::path dir = output_dir("editor-token");
  ServerUnderTest server(dir, {{"http", "127.0.0.1:0"}, {"sessions", {{{"name", "lecture"}, {"kind", "scene"}, {"style", "default"}, {"editor_token", "t3acher"},
                                              {"assets", {{{"path", kMesh.string()}}}}}}}});
  SessionClient editor(server.address(), "teacher"), visitor(server.address(), "student"), other(server.address(), "other");
  editor.join("lecture", "t3acher");
  visitor.join("lecture", "");
  other.join("lecture", "");
  try {
    SessionClient guesser(server.address(), "guesser");
    guesser.join("lecture", "teacher?");
    ADD_FAILURE() << "a wrong editor token was let in";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wrong token"), std::string::npos) << e.what();
  }

  const uint64_t seen = other.updates();
  visitor.send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  ASSERT_TRUE(eventually([&] { return visitor.refusals() == 1 && visitor.state().style.renderer == "default"; }))
      << "refusals " << visitor.refusals() << ", style " << visitor.state().style.renderer;
  EXPECT_NE(visitor.refusal().find("only the session's editors may change the style"), std::string::npos) << visitor.refusal();
  EXPECT_TRUE(visitor.connected());
  visitor.send(orbit_pose(90, 10, 2, 1));
  ASSERT_TRUE(eventually([&] { return visitor.refusals() == 2; }));

  editor.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  ASSERT_TRUE(eventually([&] { return other.state().style.renderer == "hatching" && visitor.state().style.renderer == "hatching"; }));
  EXPECT_EQ(editor.refusals(), 0u);
  EXPECT_EQ(other.refusals(), 0u);
  // The one change the other member saw was the editor's (the refused ones never reached it).
  EXPECT_EQ(other.updates(), seen + 1);
  const std::string metrics = metrics_of(server);
  EXPECT_NE(metrics.find("inkwire_changes_refused_total 2"), std::string::npos) << metrics;
}
