// Call rooms people open themselves (SPEC N6-N7), end to end on 127.0.0.1 with real
// inkwire-server and inkwire-client processes: `--new` opens a room and makes its opener the
// host, a typo without it opens nothing; the host locks the room (a newcomer is refused with
// error 11 naming the host), opens it again and removes a member (error 12; the native client
// does not come back by itself); others are refused each of these (error 10) with the reason;
// two rooms at once hear and see only their own members; an emptied room is gone after
// room_idle_seconds, and its name then opens a new, empty room with a new host key. The host's
// controls are sent by the test's own protocol clients (client/net/session_client), as a page
// sends them.
#include <array>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "client/net/session_client.hpp"
#include "common/error.hpp"
#include "making_support.hpp"
#include "protocol/framing.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
using namespace std::chrono_literals;

namespace {

// Rooms go 2 s after their last member: long enough for a member who drops to come back, short
// enough to wait for.
nlohmann::json rooms_config(nlohmann::json making = nlohmann::json::object()) {
  making["room_idle_seconds"] = 2;
  return {{"http", "127.0.0.1:0"}, {"sessions", nlohmann::json::array()}, {"making", making}};
}

// A member speaking the protocol on a socket of its own, to read what the server answers by its
// code (11 locked, 12 removed), which SessionClient turns into a sentence.
class RawMember {
 public:
  // `version`: the protocol version it says hello with and writes its join in (version 7's has
  // no open_room).
  RawMember(const ServerUnderTest& server, const std::string& name, uint16_t version = protocol::kVersion) : socket_(io_), version_(version) {
    socket_.connect(server.endpoint());
    send(protocol::Hello{.version = version, .client_name = name});
  }
  void send(const protocol::Message& m) {
    protocol::Bytes frame = protocol::encode(m);
    if (version_ < 8 && std::holds_alternative<protocol::Join>(m)) {
      frame.pop_back();
      const auto payload = uint32_t(frame.size() - protocol::kHeaderBytes);
      for (int i = 0; i < 4; ++i) frame[size_t(i)] = uint8_t(payload >> (8 * i));
    }
    asio::write(socket_, asio::buffer(frame));
  }
  // The first message `wanted` takes, or nothing when the server closed first or `patience`
  // passed.
  template <class Wanted>
  std::optional<protocol::Message> next(Wanted wanted, std::chrono::milliseconds patience = 20s) {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    for (;;) {
      while (std::optional<protocol::Message> m = decoder_.next())
        if (wanted(*m)) return m;
      std::error_code ec;
      size_t n = 0;
      bool done = false;
      socket_.async_read_some(asio::buffer(buffer_), [&](std::error_code e, size_t got) { ec = e, n = got, done = true; });
      io_.restart();
      io_.run_until(deadline);
      if (!done) {
        socket_.cancel();
        io_.restart();
        io_.run();
        return std::nullopt;
      }
      if (ec) return std::nullopt;
      decoder_.feed(buffer_.data(), n);
    }
  }
  // What a join is answered with: the snapshot, or the error.
  std::optional<protocol::Message> join(const protocol::Join& join) {
    send(join);
    return next([](const protocol::Message& m) { return std::holds_alternative<protocol::Snapshot>(m) || std::holds_alternative<protocol::ErrorMessage>(m); });
  }
  std::optional<protocol::ErrorMessage> next_error(std::chrono::milliseconds patience = 20s) {
    const auto m = next([](const protocol::Message& m) { return std::holds_alternative<protocol::ErrorMessage>(m); }, patience);
    return m ? std::optional(std::get<protocol::ErrorMessage>(*m)) : std::nullopt;
  }

 private:
  asio::io_context io_;
  asio::ip::tcp::socket socket_;
  uint16_t version_;
  std::array<uint8_t, 16384> buffer_{};
  protocol::FrameDecoder decoder_;
};

bool is_snapshot(const std::optional<protocol::Message>& m) { return m && std::holds_alternative<protocol::Snapshot>(*m); }

std::string error_text(const std::optional<protocol::Message>& m) {
  if (!m) return "(nothing: the connection closed)";
  if (const auto* e = std::get_if<protocol::ErrorMessage>(&*m)) return "error " + std::to_string(int(e->code)) + ": " + e->reason;
  return "a snapshot";
}

std::set<std::string> roster_names(const protocol::Roster& roster) {
  std::set<std::string> names;
  for (const auto& m : roster.members) names.insert(m.name);
  return names;
}

// Joins by member name in the server's log.
size_t joins_by(ServerUnderTest& server, const std::string& name) {
  size_t n = 0;
  for (const auto& j : log_events(server.process().output(), "join")) n += j.value("name", "") == name;
  return n;
}

}  // namespace

// The native members show their neutral photo: the server finds its face with dlib's model.
class RoomsE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kFaceModel) || !fs::exists(kDlibPhoto)) GTEST_SKIP() << "libdlib-data's model or libdlib-dev's example photo is missing";
  }
};

TEST_F(RoomsE2ETest, NewOpensARoomWhoseOpenerIsHostAndATypoWithoutItOpensNothing) {
  const fs::path dir = output_dir("rooms-open");
  ServerUnderTest server(dir, rooms_config());
  // Without --new an unknown name is refused, and no room is made of it.
  Process typo("inkwire-client", {"--connect", server.address(), "--session", "book-clbu", "--headless", "--frames", "1", "--out",
                                  (dir / "typo.png").string(), "--cache", (dir / "cache-typo").string()},
               dir / "typo.log");
  EXPECT_NE(typo.wait(), 0) << typo.output();
  EXPECT_NE(typo.output().find("no session named 'book-clbu'"), std::string::npos) << typo.output();
  EXPECT_EQ(metric_value(metrics_of(server), "inkwire_rooms_opened_total"), 0) << "a typo opened a room";

  // With it, the room opens for its first member, who is its host.
  auto ada = native_member(server, "book-club", dir, "Ada", {"--new"});
  ASSERT_TRUE(eventually([&] { return ada->output().find("you opened room 'book-club' and are its host") != std::string::npos; })) << ada->output();
  EXPECT_EQ(events_for(server, "room-opened", "book-club"), 1u) << server.process().output();
  SessionClient grace(server.address(), "Grace");
  const protocol::Snapshot joined = grace.join("book-club", "");
  EXPECT_EQ(joined.kind, protocol::SessionKind::Conference);
  ASSERT_TRUE(eventually([&] { return grace.roster().members.size() == 2 && named(grace.roster(), "Ada"); })) << grace.roster().members.size();
  EXPECT_EQ(grace.roster().host, named(grace.roster(), "Ada")->member) << "the opener is not the room's host";
  EXPECT_FALSE(grace.roster().locked);
  EXPECT_TRUE(grace.host_key().empty()) << "a member who joined an open room was given its key";
  // The native host shows the newcomer.
  EXPECT_TRUE(eventually([&] { return shown_members(dir, "Ada") == std::set<std::string>{"Ada", "Grace"}; })) << ada->output();

  // --new on a name that is open joins it as any member: no second room, no key.
  auto bob = native_member(server, "book-club", dir, "Bob", {"--new"});
  ASSERT_TRUE(eventually([&] { return named(grace.roster(), "Bob") != nullptr; })) << bob->output();
  EXPECT_EQ(bob->output().find("are its host"), std::string::npos) << bob->output();
  EXPECT_EQ(grace.roster().host, named(grace.roster(), "Ada")->member);
  const std::string metrics = metrics_of(server);
  EXPECT_EQ(metric_value(metrics, "inkwire_rooms_opened_total"), 1) << metrics;
  EXPECT_EQ(metric_value(metrics, "inkwire_rooms_open"), 1) << metrics;
  // Rooms are not listed on the front page.
  const std::string front = http_get(http_port(server), "GET / HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_NE(front.find("200 OK"), std::string::npos) << front;
  EXPECT_EQ(front.find("book-club"), std::string::npos) << "a room made on demand is listed on /";
  for (Process* p : {ada.get(), bob.get()}) p->kill(SIGTERM);
  EXPECT_EQ(ada->wait(), 0) << ada->output();
}

TEST_F(RoomsE2ETest, TheHostLocksOpensAndRemovesAndOthersAreRefusedEachWithTheReason) {
  const fs::path dir = output_dir("rooms-host");
  ServerUnderTest server(dir, rooms_config());
  // The host: a member that opened the room (as a page does with `open-room`).
  SessionClient host(server.address(), "Hilda");
  host.join("chess", "", true);
  ASSERT_TRUE(eventually([&] { return !host.host_key().empty(); })) << "no host key came after opening the room";
  EXPECT_EQ(host.host_key().size(), 32u);
  auto bob = native_member(server, "chess", dir, "Bob");
  SessionClient carol(server.address(), "Carol");
  carol.join("chess", "");
  ASSERT_TRUE(eventually([&] { return roster_names(host.roster()) == std::set<std::string>{"Hilda", "Bob", "Carol"}; })) << bob->output();
  const uint16_t bob_number = named(host.roster(), "Bob")->member, hilda_number = named(host.roster(), "Hilda")->member;
  EXPECT_EQ(carol.roster().host, hilda_number);

  // A member who is not host may not lock, remove or restyle, and is told why; nothing changes.
  carol.send(protocol::RoomControl{.action = protocol::RoomAction::Lock});
  ASSERT_TRUE(eventually([&] { return carol.refusals() == 1; }));
  EXPECT_NE(carol.refusal().find("only the room's host may lock it"), std::string::npos) << carol.refusal();
  carol.send(protocol::RoomControl{.action = protocol::RoomAction::Remove, .member = bob_number});
  ASSERT_TRUE(eventually([&] { return carol.refusals() == 2; }));
  EXPECT_NE(carol.refusal().find("only the room's host may"), std::string::npos) << carol.refusal();
  carol.send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  ASSERT_TRUE(eventually([&] { return carol.refusals() == 3; }));
  EXPECT_NE(carol.refusal().find("change the style"), std::string::npos) << carol.refusal();
  EXPECT_EQ(carol.state().style.renderer, "default") << "the refused style stayed on the member's own copy";
  {
    RawMember mallory(server, "Mallory");
    ASSERT_TRUE(is_snapshot(mallory.join({.session = "chess", .token = "", .open_room = false})));
    mallory.send(protocol::RoomControl{.action = protocol::RoomAction::Lock});
    const auto refused = mallory.next_error();
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->code, protocol::ErrorCode::NotAllowed) << refused->reason;
  }
  EXPECT_FALSE(host.roster().locked);
  EXPECT_TRUE(named(host.roster(), "Bob")) << "a member's removal by a non-host took effect";
  EXPECT_EQ(host.state().style.renderer, "default");

  // The host may restyle: everyone follows.
  host.send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  EXPECT_TRUE(eventually([&] { return carol.state().style.renderer == "comic"; }));
  EXPECT_EQ(host.refusals(), 0u) << host.refusal();

  // Locked: every member's roster says so, a newcomer is refused with error 11 naming the host...
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Lock});
  ASSERT_TRUE(eventually([&] { return carol.roster().locked; }));
  EXPECT_EQ(events_for(server, "room-locked", "chess"), 1u);
  {
    RawMember dave(server, "Dave");
    const auto answer = dave.join({.session = "chess", .token = "", .open_room = true});
    ASSERT_TRUE(answer && std::holds_alternative<protocol::ErrorMessage>(*answer)) << error_text(answer);
    const auto& refused = std::get<protocol::ErrorMessage>(*answer);
    EXPECT_EQ(refused.code, protocol::ErrorCode::Locked) << refused.reason;
    EXPECT_EQ(refused.reason, "room chess is locked: ask Hilda (its host) to open it");
  }
  {
    // A client of protocol version 7 knows no error 11: it is refused (9) with the same reason.
    RawMember older(server, "Olga", 7);
    const auto answer = older.join({.session = "chess", .token = "", .open_room = false});
    ASSERT_TRUE(answer && std::holds_alternative<protocol::ErrorMessage>(*answer)) << error_text(answer);
    const auto& refused = std::get<protocol::ErrorMessage>(*answer);
    EXPECT_EQ(refused.code, protocol::ErrorCode::Refused) << refused.reason;
    EXPECT_EQ(refused.reason, "room chess is locked: ask Hilda (its host) to open it");
  }
  // ... the native client too, which says so and stops,
  Process eve("inkwire-client", {"--connect", server.address(), "--session", "chess", "--headless", "--frames", "1", "--out",
                                 (dir / "eve.png").string(), "--cache", (dir / "cache-eve").string(), "--name", "Eve"},
              dir / "eve.log");
  EXPECT_NE(eve.wait(), 0) << eve.output();
  EXPECT_NE(eve.output().find("room chess is locked: ask Hilda (its host) to open it"), std::string::npos) << eve.output();
  EXPECT_EQ(joins_by(server, "Eve"), 0u);
  // ... while the host itself, coming back with its key (another tab, a reload), is let in.
  {
    SessionClient again(server.address(), "Hilda-phone");
    EXPECT_NO_THROW(again.join("chess", host.host_key()));
  }
  // Opened again, a newcomer joins.
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Unlock});
  ASSERT_TRUE(eventually([&] { return !carol.roster().locked; }));
  {
    RawMember frank(server, "Frank");
    const auto answer = frank.join({.session = "chess", .token = "", .open_room = false});
    EXPECT_TRUE(is_snapshot(answer)) << error_text(answer);
  }

  // The host removes the native member: its connection ends with the reason, everyone's roster
  // loses it, and it does not come back by itself.
  const auto removed_at = std::chrono::steady_clock::now();
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Remove, .member = bob_number});
  ASSERT_TRUE(eventually([&] { return !named(carol.roster(), "Bob"); })) << bob->output();
  EXPECT_EQ(events_for(server, "room-member-removed", "chess"), 1u);
  EXPECT_TRUE(eventually([&] { return bob->output().find("the host removed you from room chess") != std::string::npos; })) << bob->output();
  // And a protocol member removed is told so by its code, 12.
  RawMember gus(server, "Gus");
  ASSERT_TRUE(is_snapshot(gus.join({.session = "chess", .token = "", .open_room = false})));
  ASSERT_TRUE(eventually([&] { return named(host.roster(), "Gus") != nullptr; }));
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Remove, .member = named(host.roster(), "Gus")->member});
  const auto removal = gus.next_error();
  ASSERT_TRUE(removal);
  EXPECT_EQ(removal->code, protocol::ErrorCode::Removed) << removal->reason;
  EXPECT_EQ(removal->reason, "the host removed you from room chess");
  // A removal of a member that is not there is refused to the host, with the reason.
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Remove, .member = 999});
  ASSERT_TRUE(eventually([&] { return host.refusals() == 1; }));
  EXPECT_NE(host.refusal().find("no member 999"), std::string::npos) << host.refusal();
  // A native client rejoins every 2 s after a lost connection (SessionClient::kRejoinEvery):
  // three of those later, Bob has not joined again.
  ASSERT_TRUE(eventually([&] { return std::chrono::steady_clock::now() - removed_at > 3 * SessionClient::kRejoinEvery; }, 30s));
  EXPECT_EQ(joins_by(server, "Bob"), 1u) << bob->output();
  EXPECT_EQ(bob->output().find("joining again"), std::string::npos) << bob->output();
  EXPECT_FALSE(named(host.roster(), "Bob"));
  EXPECT_TRUE(carol.connected() && host.connected());
  bob->kill(SIGTERM);
  bob->wait();
}

TEST_F(RoomsE2ETest, TwoRoomsAtOnceSeeAndHearOnlyTheirOwnMembers) {
  const fs::path dir = output_dir("rooms-apart");
  ServerUnderTest server(dir, rooms_config());
  auto ada = native_member(server, "north", dir, "Ada", {"--new"});
  auto bob = native_member(server, "south", dir, "Bob", {"--new"});
  SessionClient north(server.address(), "Nia"), south(server.address(), "Sam");
  ASSERT_TRUE(eventually([&] { return ada->output().find("are its host") != std::string::npos && bob->output().find("are its host") != std::string::npos; }))
      << ada->output() << bob->output();
  north.join("north", "");
  south.join("south", "");
  ASSERT_TRUE(eventually([&] { return roster_names(north.roster()) == std::set<std::string>{"Ada", "Nia"}; })) << north.roster().members.size();
  ASSERT_TRUE(eventually([&] { return roster_names(south.roster()) == std::set<std::string>{"Bob", "Sam"}; })) << south.roster().members.size();
  EXPECT_TRUE(eventually([&] { return shown_members(dir, "Ada") == std::set<std::string>{"Ada", "Nia"}; }));
  EXPECT_TRUE(eventually([&] { return shown_members(dir, "Bob") == std::set<std::string>{"Bob", "Sam"}; }));
  // Nia speaks in the north room: a listener there hears her; Sam in the south hears nothing.
  SessionClient listener(server.address(), "Lee");
  listener.join("north", "");
  north.send(protocol::Publish{.camera = false, .microphone = true});
  const auto voice = voice_packets(50);
  for (int i = 0; i < 50; ++i) {
    north.send(protocol::VoiceFrame{.member = 0, .time_ms = uint32_t(i * 20), .opus = voice[size_t(i)]});
    std::this_thread::sleep_for(20ms);  // at the pace a microphone sends
  }
  size_t heard_north = 0;
  ASSERT_TRUE(eventually([&] { return (heard_north += listener.take_voice().size()) >= 45; })) << heard_north;
  EXPECT_TRUE(south.take_voice().empty()) << "the south room heard the north room";
  EXPECT_EQ(roster_names(south.roster()), (std::set<std::string>{"Bob", "Sam"}));
  EXPECT_EQ(shown_members(dir, "Bob"), (std::set<std::string>{"Bob", "Sam"}));
  for (Process* p : {ada.get(), bob.get()}) p->kill(SIGTERM);
}

TEST_F(RoomsE2ETest, AnEmptiedRoomIsGoneAfterItsIdleTimeAndItsNameOpensANewEmptyRoom) {
  const fs::path dir = output_dir("rooms-gone");
  ServerUnderTest server(dir, rooms_config());
  SessionClient host(server.address(), "Hilda");
  host.join("picnic", "", true);
  ASSERT_TRUE(eventually([&] { return !host.host_key().empty(); }));
  const std::string first_key = host.host_key();
  auto ada = native_member(server, "picnic", dir, "Ada");
  ASSERT_TRUE(eventually([&] { return named(host.roster(), "Ada") != nullptr; })) << ada->output();
  host.send(protocol::RoomControl{.action = protocol::RoomAction::Lock});
  ASSERT_TRUE(eventually([&] { return host.roster().locked; }));

  // While one member stays, the room stays, past its idle time.
  host.send(protocol::Leave{});
  const auto one_left = std::chrono::steady_clock::now();
  ASSERT_TRUE(eventually([&] { return std::chrono::steady_clock::now() - one_left > 3s; }));
  EXPECT_EQ(events_for(server, "room-gone", "picnic"), 0u) << "the room went while a member was in it";
  // The last member leaves: 2 s later (and a sweep) the room is gone, counted.
  ada->kill(SIGTERM);
  EXPECT_EQ(ada->wait(), 0) << ada->output();
  const auto emptied = std::chrono::steady_clock::now();
  ASSERT_TRUE(eventually([&] { return events_for(server, "room-gone", "picnic") == 1; })) << server.process().output();
  EXPECT_GE(std::chrono::steady_clock::now() - emptied, 1500ms) << "the room went before its idle time";
  const std::string metrics = metrics_of(server);
  EXPECT_EQ(metric_value(metrics, "inkwire_rooms_expired_total"), 1) << metrics;
  EXPECT_EQ(metric_value(metrics, "inkwire_rooms_open"), 0) << metrics;
  // Gone for good: joining without --new is refused; nothing of it is in the catalogue.
  {
    SessionClient late(server.address(), "Late");
    EXPECT_THROW(late.join("picnic", ""), Error);
  }
  // The name opens a new room: empty, unlocked, with a new key; the old key is no key to it.
  SessionClient again(server.address(), "Otto");
  again.join("picnic", first_key, true);
  ASSERT_TRUE(eventually([&] { return !again.host_key().empty(); })) << "no new room was opened";
  EXPECT_NE(again.host_key(), first_key);
  ASSERT_TRUE(eventually([&] { return again.roster().members.size() == 1; }));
  EXPECT_EQ(roster_names(again.roster()), std::set<std::string>{"Otto"});
  EXPECT_FALSE(again.roster().locked);
  EXPECT_EQ(events_for(server, "room-opened", "picnic"), 2u);
  // A native member opening it with --new after that is a member of this room, not a host.
  auto ned = native_member(server, "picnic", dir, "Ned", {"--new"});
  ASSERT_TRUE(eventually([&] { return named(again.roster(), "Ned") != nullptr; })) << ned->output();
  EXPECT_EQ(again.roster().host, named(again.roster(), "Otto")->member);
  ned->kill(SIGTERM);
}

TEST_F(RoomsE2ETest, WhoMayOpenRoomsFollowsThePolicy) {
  const fs::path dir = output_dir("rooms-policy");
  const auto open = [&](ServerUnderTest& server, const std::string& name, const std::vector<std::string>& extra) {
    std::vector<std::string> args{"--connect", server.address(), "--session", name, "--new", "--headless", "--frames", "1", "--out",
                                  (dir / (name + ".png")).string(), "--cache", (dir / "cache").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    auto p = std::make_unique<Process>("inkwire-client", args, dir / (name + ".log"));
    p->wait();
    return p->output();
  };
  {
    fs::create_directories(dir / "token");
    ServerUnderTest server(dir / "token", rooms_config({{"who", "token"}, {"creator_token", "c0ffee"}}));
    const std::string refused = open(server, "tea", {});
    EXPECT_NE(refused.find("only holders of this server's creator token may open call rooms"), std::string::npos) << refused;
    const std::string wrong = open(server, "tea2", {"--token", "tea"});
    EXPECT_NE(wrong.find("wrong token"), std::string::npos) << wrong;
    const std::string taken = open(server, "tea3", {"--token", "c0ffee"});
    EXPECT_NE(taken.find("you opened room 'tea3' and are its host"), std::string::npos) << taken;
    const std::string metrics = metrics_of(server);
    EXPECT_EQ(metric_value(metrics, "inkwire_making_refused_total{reason=\"token\"}"), 2) << metrics;
    EXPECT_EQ(metric_value(metrics, "inkwire_rooms_opened_total"), 1) << metrics;
  }
  {
    fs::create_directories(dir / "off");
    ServerUnderTest server(dir / "off", rooms_config({{"who", "off"}}));
    const std::string refused = open(server, "tea", {});
    EXPECT_NE(refused.find("this server does not let visitors open call rooms"), std::string::npos) << refused;
    EXPECT_EQ(metric_value(metrics_of(server), "inkwire_rooms_opened_total"), 0);
  }
}

// The caps per address leave this machine alone (a proxy on it speaks for everyone behind it),
// as the connection limits do, unless limit_loopback asks; the overall cap holds either way.
TEST_F(RoomsE2ETest, CapsPerAddressLeaveThisMachineAloneUnlessAsked) {
  const fs::path dir = output_dir("rooms-caps");
  const auto opened = [](ServerUnderTest& server, const std::string& name) {
    SessionClient opener(server.address(), "opener");
    try {
      opener.join(name, "", true);
      return std::string();
    } catch (const Error& e) {
      return std::string(e.what());
    }
  };
  // (Each opener leaves at once: its room waits, empty, far longer than the test.)
  nlohmann::json proxied = rooms_config({{"max_rooms", 4}, {"max_rooms_per_address", 2}});
  proxied["making"]["room_idle_seconds"] = 600;
  {
    fs::create_directories(dir / "proxied");
    ServerUnderTest server(dir / "proxied", proxied);
    for (const char* name : {"r1", "r2", "r3", "r4"}) EXPECT_EQ(opened(server, name), "") << name;
    EXPECT_NE(opened(server, "r5").find("this server has as many rooms open as it takes (4)"), std::string::npos);
  }
  {
    fs::create_directories(dir / "limited");
    nlohmann::json limited = proxied;
    limited["limit_loopback"] = true;
    ServerUnderTest server(dir / "limited", limited);
    EXPECT_EQ(opened(server, "r1"), "");
    EXPECT_EQ(opened(server, "r2"), "");
    const std::string refused = opened(server, "r3");
    EXPECT_NE(refused.find("your address has 2 rooms open already"), std::string::npos) << refused;
    EXPECT_EQ(metric_value(metrics_of(server), "inkwire_making_refused_total{reason=\"cap-per-address\"}"), 1);
  }
}
