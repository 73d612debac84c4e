// Sessions people make (SPEC N6-N10) without a socket: who may open a room or make a scene, the
// caps overall and per address, names, the host's key, uploads slowed per address, and rooms
// and scenes gone once unused, on a clock the test drives.
#include <chrono>
#include <filesystem>

#include <gtest/gtest.h>

#include "server/config.hpp"
#include "server/making/session_maker.hpp"
#include "server/session.hpp"
#include "server/session_registry.hpp"
#include "server/session_token.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::server;
using namespace std::chrono_literals;

namespace {

// A fresh data folder (of this test's own, emptied), for a store.
std::filesystem::path fresh_data() {
  static int made = 0;
  const std::filesystem::path dir = test::scratch_dir() / ("data-" + std::to_string(made++));
  std::filesystem::remove_all(dir);
  return dir;
}

// A store and a registry with nothing configured, and a maker over them.
struct Making {
  explicit Making(MakingOptions options, bool public_listener = false, bool limit_loopback = false)
      : store(fresh_data()), registry(store, config), maker(options, public_listener, registry, limit_loopback) {
    config.sessions.clear();
    registry.load();
  }
  ServerConfig config;
  AssetStore store;
  SessionRegistry registry;
  SessionMaker maker;
};

const SessionMaker::Clock::time_point t0{};

}  // namespace

TEST(SessionMakerTest, ARoomOpensUnderItsNameWithAHostKeyOnlyItsOpenerHolds) {
  Making m({});
  const SessionMaker::Made made = m.maker.open_room("book-club", "", "10.0.0.1", t0);
  ASSERT_TRUE(made.session) << made.refusal;
  EXPECT_EQ(made.session->state().kind, protocol::SessionKind::Conference);
  EXPECT_EQ(made.key.size(), protocol::kHostKeyChars);
  EXPECT_EQ(made.session->role_of(made.key), Role::Editor) << "the key makes its holder the host";
  EXPECT_EQ(made.session->role_of(""), Role::Visitor) << "anyone else joins as a member";
  EXPECT_FALSE(made.session->role_of("guess")) << "a wrong key is a wrong token";
  EXPECT_EQ(made.session->stored().editor_token, hash_token(made.key)) << "only the key's digest is kept";
  EXPECT_TRUE(m.store.sessions().size() == 1 && m.store.sessions()[0].maker == MadeBy::Room) << "stored as a room";
  EXPECT_EQ(m.maker.counters().rooms_opened, 1u);
}

TEST(SessionMakerTest, RandomNamesCarryNinetySixBitsAndAreUrlSafe) {
  const std::string a = SessionMaker::random_name(), b = SessionMaker::random_name();
  EXPECT_EQ(a.size(), 16u) << "96 bits in base64url";
  EXPECT_NE(a, b);
  EXPECT_EQ(a.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_"), std::string::npos);
}

TEST(SessionMakerTest, ThePolicySaysWhoMayMakeWithAReasonForTheOthers) {
  MakingOptions token{.who = MakingPolicy::Token, .who_given = true, .creator_token = "c0ffee"};
  Making m(token);
  EXPECT_NE(m.maker.open_room("a", "", "10.0.0.1", t0).refusal.find("creator token"), std::string::npos);
  EXPECT_NE(m.maker.open_room("a", "tea", "10.0.0.1", t0).refusal.find("wrong token"), std::string::npos);
  EXPECT_TRUE(m.maker.open_room("a", "c0ffee", "10.0.0.1", t0).session);
  EXPECT_NE(m.maker.may_make_scene("", "10.0.0.1").find("creator token"), std::string::npos);
  EXPECT_EQ(m.maker.may_make_scene("c0ffee", "10.0.0.1"), "");
  Making off({.who = MakingPolicy::Off, .who_given = true});
  EXPECT_NE(off.maker.open_room("a", "", "10.0.0.1", t0).refusal.find("does not let visitors"), std::string::npos);
  // Unsaid, the listeners decide: loopback ones let anyone, others ask for the token.
  EXPECT_EQ(Making({}, false).maker.policy(), MakingPolicy::Anyone);
  EXPECT_EQ(Making({}, true).maker.policy(), MakingPolicy::Token);
  EXPECT_EQ(m.maker.counters().refused.at("token"), 2u);
}

TEST(SessionMakerTest, CapsHoldOverallAndPerAddressAndNamesArePlain) {
  Making m({.max_rooms = 3, .max_rooms_per_address = 2});
  EXPECT_TRUE(m.maker.open_room("r1", "", "10.0.0.1", t0).session);
  EXPECT_TRUE(m.maker.open_room("r2", "", "10.0.0.1", t0).session);
  EXPECT_NE(m.maker.open_room("r3", "", "10.0.0.1", t0).refusal.find("your address"), std::string::npos);
  EXPECT_TRUE(m.maker.open_room("r3", "", "10.0.0.2", t0).session);
  EXPECT_NE(m.maker.open_room("r4", "", "10.0.0.3", t0).refusal.find("as many rooms"), std::string::npos);
  EXPECT_EQ(m.maker.open_rooms(), 3u);
  EXPECT_NE(m.maker.open_room("a b", "", "10.0.0.4", t0).refusal.find("letters, digits"), std::string::npos);
  EXPECT_NE(m.maker.open_room(std::string(65, 'x'), "", "10.0.0.4", t0).refusal.find("letters, digits"), std::string::npos);
}

TEST(SessionMakerTest, AnEmptyRoomGoesAfterItsIdleTimeAndItsNameOpensAFreshOne) {
  Making m({.room_idle_seconds = 300});
  ASSERT_TRUE(m.maker.open_room("book-club", "", "10.0.0.1", t0).session);
  m.maker.sweep(t0);
  m.maker.sweep(t0 + 299s);
  EXPECT_TRUE(m.registry.find("book-club")) << "still in its grace period";
  m.maker.sweep(t0 + 301s);
  EXPECT_FALSE(m.registry.find("book-club")) << "gone after 300 s without members";
  EXPECT_TRUE(m.store.sessions().empty()) << "and out of the catalogue";
  EXPECT_EQ(m.maker.counters().rooms_expired, 1u);
  const SessionMaker::Made again = m.maker.open_room("book-club", "", "10.0.0.2", t0 + 302s);
  ASSERT_TRUE(again.session) << again.refusal;
  EXPECT_EQ(again.session->stored().creator, "10.0.0.2") << "a new room";
}

TEST(SessionMakerTest, AConfiguredSessionNeverGoesAndAnUploadedSceneGoesAfterItsDay) {
  Making m({.scene_idle_seconds = 86400});
  ASSERT_TRUE(m.registry.add({.token = "", .editor_token = "", .state = fresh_session_state("configured", protocol::SessionKind::Conference, "default")}));
  const protocol::AssetAnnounce model = m.store.add_bytes(protocol::Bytes(100, 1), protocol::AssetKind::Mesh, "model.glb");
  const SessionMaker::Made scene = m.maker.make_scene(model, "10.0.0.1", t0);
  ASSERT_TRUE(scene.session) << scene.refusal;
  EXPECT_EQ(scene.session->role_of(scene.key), Role::Editor) << "its maker is its editor";
  EXPECT_EQ(scene.session->state().assets, std::vector<protocol::AssetAnnounce>{model});
  m.maker.sweep(t0 + 86399s);
  EXPECT_TRUE(m.registry.find(scene.session->name()));
  m.maker.sweep(t0 + 86401s);
  EXPECT_FALSE(m.registry.find(scene.session->name())) << "unvisited for a day";
  m.maker.sweep(t0 + 1000000s);
  EXPECT_TRUE(m.registry.find("configured")) << "the operator's sessions stay";
}

TEST(SessionMakerTest, UploadsFromOneAddressAreSlowedPastTheirRate) {
  Making m({.uploads_per_minute_per_address = 20});
  double wait = 0;
  int taken = 0;
  for (int i = 0; i < 50; ++i) {  // 50 in the same moment
    if (m.maker.take_upload("10.0.0.1", t0, &wait).empty()) {
      ++taken;
      m.maker.upload_done("10.0.0.1");
    }
  }
  EXPECT_EQ(taken, 20) << "a minute's worth at once, then slowed";
  EXPECT_GT(wait, 0.0);
  EXPECT_TRUE(m.maker.take_upload("10.0.0.2", t0, &wait).empty()) << "other addresses are not slowed";
  m.maker.upload_done("10.0.0.2");
  EXPECT_TRUE(m.maker.take_upload("10.0.0.1", t0 + 4s, &wait).empty()) << "one again after 3 s";
}

// A proxy on this machine speaks for many people: the per-address limits leave 127.0.0.1 and ::1
// to the overall caps, as they do for connections, unless the config's limit_loopback asks.
TEST(SessionMakerTest, ThisMachinesAddressesAreLeftToTheOverallCapsUnlessAsked) {
  Making m({.max_rooms = 4, .max_rooms_per_address = 2, .uploads_per_minute_per_address = 1});
  for (const char* name : {"r1", "r2", "r3"}) EXPECT_TRUE(m.maker.open_room(name, "", "127.0.0.1", t0).session) << name;
  EXPECT_TRUE(m.maker.open_room("r4", "", "::1", t0).session);
  EXPECT_NE(m.maker.open_room("r5", "", "127.0.0.1", t0).refusal.find("as many rooms"), std::string::npos) << "the overall cap still holds";
  double wait = 0;
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(m.maker.take_upload("127.0.0.1", t0, &wait), "") << i;
    m.maker.upload_done("127.0.0.1");
  }
  Making limited({.max_rooms = 4, .max_rooms_per_address = 2, .uploads_per_minute_per_address = 1}, false, true);
  EXPECT_TRUE(limited.maker.open_room("r1", "", "127.0.0.1", t0).session);
  EXPECT_TRUE(limited.maker.open_room("r2", "", "127.0.0.1", t0).session);
  EXPECT_NE(limited.maker.open_room("r3", "", "127.0.0.1", t0).refusal.find("your address"), std::string::npos);
  EXPECT_EQ(limited.maker.take_upload("127.0.0.1", t0, &wait), "");
  limited.maker.upload_done("127.0.0.1");
  EXPECT_NE(limited.maker.take_upload("127.0.0.1", t0, &wait).find("too many uploads"), std::string::npos);
}

// Uploads being received are bounded per address and in all; imports apart from them, so a
// sender whose body stalls holds no import's place.
TEST(SessionMakerTest, UploadsAtOnceAreBoundedPerAddressAndImportsApart) {
  Making m({.uploads_per_minute_per_address = 100});
  double wait = 0;
  EXPECT_EQ(m.maker.take_upload("10.0.0.1", t0, &wait), "");
  EXPECT_EQ(m.maker.take_upload("10.0.0.1", t0, &wait), "");
  EXPECT_NE(m.maker.take_upload("10.0.0.1", t0, &wait).find("your address is sending 2 uploads already"), std::string::npos);
  EXPECT_GT(wait, 0.0);
  for (int i = 0; i < SessionMaker::kMaxUploadsAtOnce - 2; ++i) EXPECT_EQ(m.maker.take_upload("10.0.1." + std::to_string(i), t0, &wait), "") << i;
  EXPECT_NE(m.maker.take_upload("10.0.0.9", t0, &wait).find("as many uploads as it takes"), std::string::npos);
  m.maker.upload_done("10.0.0.1");
  EXPECT_EQ(m.maker.take_upload("10.0.0.1", t0, &wait), "") << "one ended: its sender may send another";
  EXPECT_TRUE(m.maker.take_import());
  EXPECT_TRUE(m.maker.take_import());
  EXPECT_FALSE(m.maker.take_import()) << "two imports at once";
  m.maker.import_done();
  EXPECT_TRUE(m.maker.take_import());
  EXPECT_EQ(m.maker.counters().refused.at("busy-address"), 1u);
}
