// Several server instances sharing sessions through a real Redis on 127.0.0.1 (SPEC D1): a
// change made on one instance reaches members on the other, a late joiner there gets it from the
// snapshot, an asset added on one is downloaded from the other (hash checked), and a broker
// killed and restarted in the middle loses nothing. Skipped with a message without
// redis-server (Debian package redis-server).
#include <asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"
#include "common/content_hash.hpp"
#include "common/model_bundle.hpp"
#include "broker_support.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
namespace fs = std::filesystem;

namespace {

const fs::path kMesh = fs::path(INKWIRE_MESH_DIR) / "cow.off";

nlohmann::json instance_config(const std::string& name, const BrokerUnderTest& broker, nlohmann::json sessions) {
  return {{"name", name}, {"broker", broker.url()}, {"http", "127.0.0.1:0"}, {"sessions", std::move(sessions)}};
}

std::string health_of(ServerUnderTest& server) { return http_get(http_port(server), "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"); }

// Instance one defines the session "cows"; instance two defines none and learns it from the broker.
nlohmann::json cows() { return {{{"name", "cows"}, {"kind", "scene"}, {"style", "default"}, {"assets", {{{"path", kMesh.string()}}}}}}; }

size_t count_events(ServerUnderTest& server, const std::string& event) { return log_events(server.process().output(), event).size(); }

fs::path with_instance_folders(const fs::path& dir) {
  fs::create_directories(dir / "one");
  fs::create_directories(dir / "two");
  return dir;
}

// A broker and two instances on it: "one" defines the session "cows", "two" none of its own (it
// adopts "cows" from the broker, mesh included).
struct TwoInstances {
  explicit TwoInstances(const fs::path& dir)
      : broker(with_instance_folders(dir)),
        one(dir / "one", instance_config("one", broker, cows())),
        two(dir / "two", instance_config("two", broker, nlohmann::json::array())) {
    EXPECT_TRUE(eventually([&] { return count_events(two, "session-added") == 1; })) << two.process().output();
  }
  BrokerUnderTest broker;
  ServerUnderTest one, two;
};

}  // namespace

class BrokerE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kRedis)) GTEST_SKIP() << kRedis << " is missing (Debian package redis-server)";
    if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  }
};

TEST_F(BrokerE2ETest, AChangeOnOneInstanceReachesTheOtherWithinTwoFramesAndALateJoinerThereGetsIt) {
  const fs::path dir = output_dir("broker-two-instances");
  TwoInstances instances(dir);
  ServerUnderTest &one = instances.one, &two = instances.two;

  // A member on instance two downloads the mesh that was added on instance one.
  {
    SessionClient probe(two.address(), "probe");
    const protocol::Snapshot state = probe.join("cows", "");
    AssetCache cache(dir / "cache-probe");
    const std::vector<fs::path> files = probe.fetch_assets(state, cache);
    ASSERT_EQ(files.size(), 1u);
    const std::vector<uint8_t> whole = self_contained_model(kMesh)->bytes;  // the OFF as one GLB, as instance one stored it
    EXPECT_EQ(content_hash_of_file(files[0]), content_hash(whole.data(), whole.size())) << "the mesh on instance two is not the one added on instance one";
  }

  const int frames = 30, fps = 10;
  auto b = headless_client(two, "cows", dir, "b", frames, fps);
  ASSERT_TRUE(eventually([&] { return frame_log(dir / "b.jsonl").size() >= 3; })) << b->output();
  SessionClient a(one.address(), "a");
  a.join("cows", "");
  const int64_t sent_us = monotonic_us();
  a.send(protocol::StyleChange{.renderer = "comic", .settings = {"shade_map=two-tone"}});
  a.send(orbit_pose(120, 30, 1.3f, 1));
  const protocol::Snapshot changed = a.state();
  ASSERT_EQ(b->wait(), 0) << b->output();

  const auto log = frame_log(dir / "b.jsonl");
  ASSERT_EQ(log.size(), size_t(frames));
  int stale = 0;  // frames drawn after the change was sent that still show the old state
  for (const auto& f : log)
    if (f["monotonic_us"].get<int64_t>() > sent_us && f["revision"].get<uint32_t>() < changed.revision) ++stale;
  EXPECT_LE(stale, 2) << "instance two's member lagged more than two frames behind instance one";
  EXPECT_EQ(log.back()["revision"].get<uint32_t>(), changed.revision);
  EXPECT_EQ(log.back()["style"].get<std::string>(), "comic shade_map=two-tone");

  auto late = headless_client(two, "cows", dir, "late", 1, 10);
  ASSERT_EQ(late->wait(), 0) << late->output();
  const auto first = frame_log(dir / "late.jsonl").at(0);
  EXPECT_EQ(first["revision"].get<uint32_t>(), changed.revision);
  EXPECT_EQ(first["style"].get<std::string>(), "comic shade_map=two-tone");
}

TEST_F(BrokerE2ETest, ABrokerKilledAndRestartedLosesNothingAndChangesFlowAgain) {
  TwoInstances instances(output_dir("broker-restart"));
  BrokerUnderTest& broker = instances.broker;
  ServerUnderTest &one = instances.one, &two = instances.two;

  SessionClient a(one.address(), "a"), b(two.address(), "b");
  a.join("cows", "");
  b.join("cows", "");
  a.send(orbit_pose(40, 10, 1.4f, 1));
  ASSERT_TRUE(eventually([&] { return b.state().camera.sequence == 1; })) << "no change crossed before the broker went away";
  // Changes are published by the script's digest; a broker that forgot its scripts is given the text.
  ASSERT_EQ(broker.cli({"SCRIPT", "FLUSH"}), 0);
  a.send(orbit_pose(40, 10, 1.4f, 2));
  ASSERT_TRUE(eventually([&] { return b.state().camera.sequence == 2; })) << "a change was lost when the broker forgot its scripts";

  EXPECT_NE(metrics_of(one).find("inkwire_broker_up 1"), std::string::npos) << metrics_of(one);
  broker.kill();
  ASSERT_TRUE(eventually([&] { return count_events(one, "broker-lost") >= 1 && count_events(two, "broker-lost") >= 1; }))
      << one.process().output() << two.process().output();
  // An operator sees it, and a load balancer keeps sending members: the instance still serves.
  EXPECT_NE(metrics_of(one).find("inkwire_broker_up 0"), std::string::npos) << metrics_of(one);
  const std::string health = health_of(one);
  EXPECT_NE(health.find("200 OK"), std::string::npos) << health;
  EXPECT_NE(health.find("broker away"), std::string::npos) << health;
  // Made while the broker is away: instance one's own members still get it at once...
  SessionClient a2(one.address(), "a2");
  a2.join("cows", "");
  a.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  EXPECT_TRUE(eventually([&] { return a2.state().style.renderer == "hatching"; })) << "instance one stopped serving its own members";
  // ... and so are newcomers on instance two, from what two has.
  SessionClient b2(two.address(), "b2");
  EXPECT_EQ(b2.join("cows", "").camera.sequence, 2u);

  broker.start();  // empty: the instances must put sessions, assets and state back
  ASSERT_TRUE(eventually([&] { return count_events(one, "broker-connected") >= 2 && count_events(two, "broker-connected") >= 2; }, std::chrono::seconds(30)))
      << one.process().output() << two.process().output();
  EXPECT_TRUE(eventually([&] { return b.state().style.renderer == "hatching"; })) << "the change made while the broker was away was lost";
  const std::string metrics = metrics_of(one);
  EXPECT_NE(metrics.find("inkwire_broker_up 1"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("inkwire_broker_reconnects_total 1"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("inkwire_broker_unsent 0"), std::string::npos) << metrics;
  a.send(orbit_pose(200, 25, 1.2f, 3));
  EXPECT_TRUE(eventually([&] { return b.state().camera.sequence == 3 && b2.state().camera.sequence == 3; })) << "changes do not flow after the broker came back";
  // Every member agrees on the whole state, and the count of changes: none was lost or counted twice.
  EXPECT_EQ(b.state().style, a.state().style);
  EXPECT_EQ(b.state().camera, a.state().camera);
  for (const std::string& address : {one.address(), two.address()}) {
    SessionClient late(address, "late");
    const protocol::Snapshot joined = late.join("cows", "");
    EXPECT_EQ(joined.style.renderer, "hatching");
    EXPECT_EQ(joined.camera.sequence, 3u);
    EXPECT_EQ(joined.revision, a.state().revision) << "a late joiner on " << address;
  }
}

TEST_F(BrokerE2ETest, ABrokerWithAPasswordServesInstancesThatKnowItAndRefusesOthersWithTheReason) {
  const fs::path dir = with_instance_folders(output_dir("broker-password"));
  BrokerUnderTest broker(dir, "hunter2");
  nlohmann::json right = instance_config("one", broker, cows()), wrong = instance_config("two", broker, nlohmann::json::array());
  right["broker"] = broker.url("hunter2");
  wrong["broker"] = broker.url("guess");
  ServerUnderTest one(dir / "one", right);
  ServerUnderTest two(dir / "two", wrong);
  EXPECT_TRUE(eventually([&] { return count_events(one, "broker-connected") == 1; })) << one.process().output();
  EXPECT_TRUE(eventually([&] { return two.process().output().find("the broker refused the password") != std::string::npos; })) << two.process().output();
  EXPECT_EQ(count_events(two, "session-added"), 0u) << "an instance without the password got the sessions";
  // It still serves what it has (nothing here) and keeps trying; the other is unaffected.
  EXPECT_TRUE(two.process().running());
  SessionClient a(one.address(), "a");
  EXPECT_NO_THROW(a.join("cows", ""));
}

// A call across instances (SPEC F12): a member publishing on instance one is in the roster of a
// listener on instance two (its photo fetched from instance two), and its face codes and voice
// reach that listener under instance two's number for it.
TEST_F(BrokerE2ETest, AMemberPublishingOnOneInstanceIsSeenAndHeardOnTheOther) {
  const fs::path photo_file = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";
  if (!fs::exists(photo_file)) GTEST_SKIP() << "libdlib-dev's example photo is missing";
  const fs::path dir = output_dir("broker-call");
  with_instance_folders(dir);
  BrokerUnderTest broker(dir);
  ServerUnderTest one(dir / "one", instance_config("one", broker, {{{"name", "call"}, {"kind", "conference"}}}));
  ServerUnderTest two(dir / "two", instance_config("two", broker, nlohmann::json::array()));
  ASSERT_TRUE(eventually([&] { return count_events(two, "session-added") == 1; })) << two.process().output();

  SessionClient listener(two.address(), "Listener"), ada(one.address(), "Ada");
  listener.join("call", "");
  ada.join("call", "");
  const Image photo = load_image(photo_file);
  ada.send(protocol::Publish{.camera = true, .microphone = true});
  ada.send(protocol::NeutralPhoto{.jpeg = encode_image(photo, "jpg", 90)});
  ASSERT_TRUE(eventually([&] {
    const protocol::CallMember* m = named(listener.roster(), "Ada");
    return m && m->assets.size() == 2 && m->camera;
  })) << "instance two's roster: " << listener.roster().members.size() << " members";
  const protocol::CallMember remote = *named(listener.roster(), "Ada");
  AssetCache cache(dir / "cache");
  EXPECT_EQ(load_image(listener.fetch_asset(remote.assets[0], cache)).width, photo.width) << "the photo, served by instance two";

  const auto voice = voice_packets(60);
  for (int k = 0; k < 60; ++k) {
    if (k % 5 == 0) {
      const Image shown = photo.width > 320 ? resized(photo, 320, photo.height * 320 / photo.width) : photo;
      ada.send(protocol::FaceCrop{.time_ms = uint32_t(k * 20), .frame_width = uint16_t(shown.width), .frame_height = uint16_t(shown.height),
                                  .x = 0, .y = 0, .width = uint16_t(shown.width), .height = uint16_t(shown.height), .jpeg = encode_image(shown, "jpg", 80)});
    }
    ada.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(k * 20), .opus = voice[size_t(k)]});
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(eventually([&] { return listener.member_faces().count(remote.member) > 0; })) << "no face of Ada reached instance two";
  // Every packet in flight lands (or the wait ends and says how many did).
  size_t heard = 0;
  eventually([&] {
    for (const auto& [v, arrived] : listener.take_voice()) {
      EXPECT_EQ(v.member, remote.member) << "a voice packet under another number";
      ++heard;
    }
    return heard >= 60;
  });
  EXPECT_GE(heard, 55u) << "of 60 voice packets sent on instance one";

  ada.send(protocol::Leave{});
  EXPECT_TRUE(eventually([&] { return !named(listener.roster(), "Ada"); })) << "Ada left instance one but stays in instance two's roster";
}

// One loudest-K across the call, not K per instance (SPEC F19): with call_loudest 1, Ada speaking
// softly on instance one and Bea loudly on instance two, a listener on instance one hears Bea
// alone (before, each instance relayed its own loudest: both).
TEST_F(BrokerE2ETest, TheLoudestFewAreTheCallsWhicheverInstanceTheySpeakOn) {
  const fs::path dir = output_dir("broker-loudest");
  with_instance_folders(dir);
  BrokerUnderTest broker(dir);
  nlohmann::json first = instance_config("one", broker, {{{"name", "call"}, {"kind", "conference"}}}), second = instance_config("two", broker, nlohmann::json::array());
  first["call_loudest"] = second["call_loudest"] = 1;
  ServerUnderTest one(dir / "one", first), two(dir / "two", second);
  ASSERT_TRUE(eventually([&] { return count_events(two, "session-added") == 1; })) << two.process().output();
  SessionClient listener(one.address(), "Listener"), ada(one.address(), "Ada"), bea(two.address(), "Bea");
  for (SessionClient* c : {&listener, &ada, &bea}) c->join("call", "");
  ada.send(protocol::Publish{.camera = false, .microphone = true});
  bea.send(protocol::Publish{.camera = false, .microphone = true});
  ASSERT_TRUE(eventually([&] { return named(listener.roster(), "Ada") && named(listener.roster(), "Bea"); }));
  const uint16_t ada_number = named(listener.roster(), "Ada")->member, bea_number = named(listener.roster(), "Bea")->member;
  const auto soft = voice_packets(100, 0.1f), loud = voice_packets(100, 1.0f);
  for (int k = 0; k < 100; ++k) {
    ada.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(k * 20), .opus = soft[size_t(k)]});
    bea.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(k * 20), .opus = loud[size_t(k)]});
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // Bea's packets in flight land (or the wait ends and says how many did); whatever of Ada's
  // came meanwhile is counted too.
  size_t from_ada = 0, from_bea = 0;
  eventually([&] {
    for (const auto& [v, arrived] : listener.take_voice()) (v.member == ada_number ? from_ada : v.member == bea_number ? from_bea : from_ada) += 1;
    return from_bea >= 100;
  });
  std::printf("  the listener heard %zu of Bea's packets (loud, instance two) and %zu of Ada's (soft, its own instance)\n", from_bea, from_ada);
  EXPECT_GE(from_bea, 80u) << "the loudest speaker of the call, on the other instance, is not heard";
  EXPECT_LE(from_ada, 10u) << "the listener's own instance relayed its own loudest beside the call's";
}

// A broker that stops answering without closing its sockets (SIGSTOP) is noticed by the PING
// heartbeat within its deadline (3 s): the instance says so and serves its own members; when the
// broker answers again, changes flow between the instances again.
TEST_F(BrokerE2ETest, ASilentBrokerIsNoticedWithinTheHeartbeatsDeadlineAndChangesFlowWhenItAnswersAgain) {
  const fs::path dir = output_dir("broker-silent");
  TwoInstances instances(dir);
  ServerUnderTest &one = instances.one, &two = instances.two;
  ASSERT_TRUE(eventually([&] { return health_of(one) .find("ok\n") != std::string::npos; }));
  instances.broker.signal(SIGSTOP);
  const auto stopped = std::chrono::steady_clock::now();
  ASSERT_TRUE(eventually([&] { return count_events(one, "broker-lost") >= 1; }, std::chrono::seconds(8))) << one.process().output();
  const double noticed = std::chrono::duration<double>(std::chrono::steady_clock::now() - stopped).count();
  std::printf("a silent broker noticed after %.1f s\n", noticed);
  EXPECT_LT(noticed, 5.0) << "the heartbeat's deadline is 3 s, checked each second";
  EXPECT_NE(log_events(one.process().output(), "broker-lost").front().value("reason", "").find("PING"), std::string::npos);
  EXPECT_NE(health_of(one).find("broker away"), std::string::npos) << health_of(one);
  // Its own members are still served meanwhile.
  SessionClient local(one.address(), "local");
  local.join("cows", "");
  instances.broker.signal(SIGCONT);
  ASSERT_TRUE(eventually([&] { return count_events(one, "broker-connected") >= 2; }, std::chrono::seconds(60))) << one.process().output();
  SessionClient watcher(two.address(), "watcher");
  watcher.join("cows", "");
  local.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  EXPECT_TRUE(eventually([&] { return watcher.state().style.renderer == "hatching"; }, std::chrono::seconds(60))) << "no change flowed after the broker answered again";
}
