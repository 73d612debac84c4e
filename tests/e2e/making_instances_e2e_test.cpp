// Sessions people make, across instances (SPEC N6-N8 with D1): two inkwire-server instances on
// a real Redis on 127.0.0.1. A room opened on instance one (`inkwire-client --new`) is joined
// from instance two and each side's native member shows the other, and the host's lock and
// removal hold there too; a scene uploaded to instance one is joined and drawn from instance
// two (its model fetched through two), and its editor's new model reaches a member there, who
// draws it. Skipped with a message without redis-server.
#include <set>

#include <gtest/gtest.h>

#include "client/net/session_client.hpp"
#include "client/viewer/session_content.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/image_metrics.hpp"
#include "broker_support.hpp"
#include "making_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
using namespace std::chrono_literals;

namespace {

const fs::path kBox = "/usr/share/assimp/models/glTF2/BoxTextured-glTF";
const std::vector<fs::path> kBoxFiles = {kBox / "BoxTextured.gltf", kBox / "BoxTextured0.bin", kBox / "CesiumLogoFlat.png"};
const fs::path kJeep = "/usr/share/assimp/models/MS3D";

fs::path with_instance_folders(const fs::path& dir) {
  fs::create_directories(dir / "one");
  fs::create_directories(dir / "two");
  return dir;
}

nlohmann::json instance_config(const std::string& name, const BrokerUnderTest& broker) {
  return {{"name", name}, {"broker", broker.url()}, {"http", "127.0.0.1:0"}, {"sessions", nlohmann::json::array()},
          {"making", {{"room_idle_seconds", 2}}}};
}

struct TwoInstances {
  explicit TwoInstances(const fs::path& dir)
      : broker(with_instance_folders(dir)), one(dir / "one", instance_config("one", broker)), two(dir / "two", instance_config("two", broker)) {
    EXPECT_TRUE(eventually([&] { return log_events(one.process().output(), "broker-connected").size() == 1 &&
                                        log_events(two.process().output(), "broker-connected").size() == 1; }))
        << one.process().output() << two.process().output();
  }
  BrokerUnderTest broker;
  ServerUnderTest one, two;
};

}  // namespace

class MakingInstancesE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kRedis)) GTEST_SKIP() << kRedis << " is missing (Debian package redis-server)";
    if (!fs::exists(kBox)) GTEST_SKIP() << kBox << " is missing (Debian package assimp-testmodels)";
    if (!fs::exists(kFaceModel) || !fs::exists(kDlibPhoto)) GTEST_SKIP() << "libdlib-data's model or libdlib-dev's example photo is missing";
  }
};

TEST_F(MakingInstancesE2ETest, ARoomOpenedOnOneInstanceIsJoinedFromTheOther) {
  const fs::path dir = output_dir("making-instances-room");
  TwoInstances instances(dir);
  ServerUnderTest &one = instances.one, &two = instances.two;
  auto ada = native_member(one, "crossing", dir, "Ada", {"--new"});
  ASSERT_TRUE(eventually([&] { return ada->output().find("you opened room 'crossing' and are its host") != std::string::npos; })) << ada->output();
  ASSERT_TRUE(eventually([&] { return events_for(two, "session-added", "crossing") == 1; })) << two.process().output();
  // Joined on instance two without --new: the room is there.
  auto bob = native_member(two, "crossing", dir, "Bob");
  EXPECT_TRUE(eventually([&] { return shown_members(dir, "Ada") == std::set<std::string>{"Ada", "Bob"}; })) << ada->output();
  EXPECT_TRUE(eventually([&] { return shown_members(dir, "Bob") == std::set<std::string>{"Ada", "Bob"}; })) << bob->output();
  EXPECT_EQ(events_for(two, "room-opened", "crossing"), 0u) << "instance two opened a second room of the name";
  EXPECT_EQ(bob->output().find("are its host"), std::string::npos);
  // Opened once: instance one counts it, instance two serves it.
  EXPECT_EQ(metric_value(metrics_of(one), "inkwire_rooms_opened_total"), 1);
  for (Process* p : {ada.get(), bob.get()}) p->kill(SIGTERM);
  EXPECT_EQ(ada->wait(), 0) << ada->output();
  EXPECT_EQ(bob->wait(), 0) << bob->output();
  // Empty on both, it goes on both.
  EXPECT_TRUE(eventually([&] { return events_for(one, "room-gone", "crossing") == 1; }, 30s)) << one.process().output();
  EXPECT_TRUE(eventually([&] { return events_for(two, "room-gone", "crossing") + events_for(two, "session-removed", "crossing") == 1; }, 30s))
      << two.process().output();
  SessionClient late(two.address(), "late");
  EXPECT_THROW(late.join("crossing", ""), Error) << "the room outlived its members on instance two";
}

TEST_F(MakingInstancesE2ETest, ASceneUploadedToOneInstanceIsDrawnFromTheOtherAndItsNewModelReachesMembersThere) {
  const fs::path dir = output_dir("making-instances-scene");
  TwoInstances instances(dir);
  ServerUnderTest &one = instances.one, &two = instances.two;
  const HttpAnswer made = upload_files(http_port(one), kBoxFiles);
  ASSERT_EQ(made.status, 201) << made.raw;
  const std::string name = made.json().value("name", ""), key = made.json().value("editor_key", "");
  ASSERT_TRUE(eventually([&] { return events_for(two, "session-added", name) == 1; })) << two.process().output();
  auto viewer = headless_client(two, name, dir, "viewer", 1, 10);
  ASSERT_EQ(viewer->wait(), 0) << viewer->output();
  Process render("inkwire-render", {"--mesh", kBoxFiles[0].string(), "--style", "comic-extended", "--view", "30,20,1.4", "--size", "240x180", "--out",
                                    (dir / "render.png").string()},
                 dir / "render.log");
  ASSERT_EQ(render.wait(), 0) << render.output();
  EXPECT_GE(psnr(load_image(client_frame(dir, "viewer", 0)), load_image(dir / "render.png")), 35.0) << "instance two's member drew another box";

  // The editor (on instance one) replaces the model: a member on instance two gets it.
  SessionClient member(two.address(), "member");
  const protocol::Snapshot first = member.join(name, "");
  const HttpAnswer replaced =
      upload_files(http_port(one), {kJeep / "jeep1.ms3d", kJeep / "jeep1.jpg"}, "/scenes/" + name + "/model", "X-Inkwire-Editor-Key: " + key + "\r\n");
  ASSERT_EQ(replaced.status, 200) << replaced.raw;
  ASSERT_TRUE(eventually([&] { return member.state().assets != first.assets; }, 30s)) << "the new model did not reach instance two's member";
  EXPECT_EQ(member.state().assets.at(0).name, "jeep1.glb");
  EXPECT_EQ(member.state().camera, first.camera);
  auto after = headless_client(two, name, dir, "after", 1, 10);
  ASSERT_EQ(after->wait(), 0) << after->output();
  Process jeep("inkwire-render", {"--mesh", (kJeep / "jeep1.ms3d").string(), "--style", "comic-extended", "--view", "30,20,1.4", "--size", "240x180",
                                  "--out", (dir / "jeep.png").string()},
               dir / "jeep.log");
  ASSERT_EQ(jeep.wait(), 0) << jeep.output();
  EXPECT_GE(psnr(load_image(client_frame(dir, "after", 0)), load_image(dir / "jeep.png")), 35.0) << "instance two draws another model than the jeep";
}

TEST_F(MakingInstancesE2ETest, ARoomLockedOnOneInstanceTakesNoNewcomerOnTheOther) {
  const fs::path dir = output_dir("making-instances-lock");
  TwoInstances instances(dir);
  ServerUnderTest &one = instances.one, &two = instances.two;
  SessionClient host(one.address(), "Hilda");
  host.join("guarded", "", true);
  ASSERT_TRUE(eventually([&] { return !host.host_key().empty(); }));
  ASSERT_TRUE(eventually([&] { return events_for(two, "session-added", "guarded") == 1; })) << two.process().output();
  SessionClient guest(two.address(), "Gail");
  guest.join("guarded", "");
  ASSERT_TRUE(eventually([&] { return named(host.roster(), "Gail") != nullptr && named(guest.roster(), "Hilda") != nullptr; }));
  EXPECT_EQ(guest.roster().host, named(guest.roster(), "Hilda")->member) << "instance two's roster does not name the host";
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Lock});
  ASSERT_TRUE(eventually([&] { return host.roster().locked; }));
  EXPECT_TRUE(eventually([&] { return guest.roster().locked; }, 10s)) << "instance two's members are not told the room is locked";
  {
    SessionClient newcomer(two.address(), "Nat");
    try {
      newcomer.join("guarded", "");
      ADD_FAILURE() << "a newcomer on instance two joined a locked room";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("room guarded is locked: ask Hilda (its host) to open it"), std::string::npos) << e.what();
    }
  }
  // The host removes the member on instance two: it is closed there with the reason.
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Remove, .member = named(host.roster(), "Gail")->member});
  EXPECT_TRUE(eventually([&] { return !guest.connected(); }, 10s)) << host.refusal();
  EXPECT_NE(guest.last_error().find("the host removed you from room guarded"), std::string::npos) << guest.last_error();
  EXPECT_TRUE(eventually([&] { return named(host.roster(), "Gail") == nullptr; }));
  // Opened again, instance two takes newcomers.
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Unlock});
  EXPECT_TRUE(eventually([&] {
    SessionClient again(two.address(), "Nat");
    try {
      again.join("guarded", "");
      return true;
    } catch (const Error&) {
      return false;
    }
  }, 10s)) << "instance two stayed locked";
  EXPECT_EQ(host.refusals(), 0u) << host.refusal();
}
