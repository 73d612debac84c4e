// A call's roster, intake and face budget (server/call/) with members that are no sockets: fake
// peers that keep what the call sends them, and a relay that keeps what it shares.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>
#include <variant>

#include "protocol/framing.hpp"
#include "server/call/call.hpp"
#include "server/call/call_peer.hpp"
#include "server/relay/relay.hpp"
#include "tests/unit/open_sockets.hpp"

namespace inkwire::server {
namespace {

using namespace std::chrono_literals;

class FakePeer final : public CallPeer {
 public:
  FakePeer(uint64_t id, std::string address) : id_(id), address_(std::move(address)) {}
  void send(const protocol::Message& message) override { received.push_back(message); }
  void send_frame(std::shared_ptr<const protocol::Bytes> frame, protocol::MessageType) override {
    received.push_back(protocol::decode_frame(frame->data(), frame->size()));
  }
  void close_with(protocol::ErrorCode code, const std::string& reason) override { closed = {code, reason}; }
  uint64_t id() const override { return id_; }
  uint16_t version() const override { return protocol::kVersion; }
  const std::string& address() const override { return address_; }
  std::chrono::steady_clock::duration silent_for() const override { return silent; }

  template <class T>
  std::vector<T> all() const {
    std::vector<T> out;
    for (const auto& m : received)
      if (const auto* t = std::get_if<T>(&m)) out.push_back(*t);
    return out;
  }
  protocol::Roster roster() const {
    const auto rosters = all<protocol::Roster>();
    return rosters.empty() ? protocol::Roster{} : rosters.back();
  }

  std::vector<protocol::Message> received;
  std::optional<std::pair<protocol::ErrorCode, std::string>> closed;
  std::chrono::steady_clock::duration silent{};

 private:
  uint64_t id_;
  std::string address_;
};

class KeepingRelay final : public Relay {
 public:
  void start() override {}
  void stop() override {}
  void publish(Session&, const protocol::Message&, uint64_t) override {}
  RelayStatus status() const override { return {}; }
  void share_call(const CallShare&) override { ++shared; }
  int shared = 0;
};

std::vector<std::string> names(const protocol::Roster& roster) {
  std::vector<std::string> out;
  for (const auto& m : roster.members) out.push_back(m.name);
  return out;
}

class CallRosterTest : public ::testing::Test {
 protected:
  void TearDown() override { EXPECT_EQ(test::open_sockets(), 0) << "the call's unit tests open no socket"; }
  std::shared_ptr<FakePeer> peer(uint64_t id, const std::string& address = "10.0.0.1") { return std::make_shared<FakePeer>(id, address); }
  // Nothing here reaches the analyst's thread (no crop is a JPEG): its results never come.
  CallAnalyst analyst{[](CallAnalyst::Result) {}};
  Call::Counters counters;
  KeepingRelay relay;
  Call call{"room", CallOptions{}, analyst, counters, relay, "here"};
};

TEST_F(CallRosterTest, EveryMemberHearsTheRosterAsItChangesEachToldWhichItIs) {
  const auto ada = peer(1), bea = peer(2, "10.0.0.2");
  call.join(ada, "ada");
  EXPECT_EQ(names(ada->roster()), (std::vector<std::string>{"ada"}));
  call.join(bea, "bea", true);
  for (const auto& p : {ada, bea}) EXPECT_EQ(names(p->roster()), (std::vector<std::string>{"ada", "bea"}));
  const uint16_t ada_number = ada->roster().you, bea_number = bea->roster().you;
  EXPECT_NE(ada_number, 0);
  EXPECT_NE(bea_number, 0);
  EXPECT_NE(ada_number, bea_number);
  EXPECT_EQ(ada->roster().host, bea_number);
  call.leave(bea->id());
  EXPECT_EQ(names(ada->roster()), (std::vector<std::string>{"ada"}));
  EXPECT_EQ(ada->roster().host, 0);
  EXPECT_EQ(call.size(), 1u);
  EXPECT_GT(relay.shared, 0);  // other instances hear each roster too
}

TEST_F(CallRosterTest, OneWhoComesBackTakesItsOwnNumberAndASilentTwinGivesWay) {
  const auto ada = peer(1), bea = peer(2, "10.0.0.2");
  call.join(ada, "ada");
  call.join(bea, "bea");
  const uint16_t bea_number = bea->roster().you;
  call.leave(bea->id());
  const auto bea_again = peer(3, "10.0.0.2");
  call.join(bea_again, "bea");
  EXPECT_EQ(bea_again->roster().you, bea_number);
  // The same name from another address is someone else.
  const auto other_bea = peer(4, "10.0.0.9");
  call.join(other_bea, "bea");
  EXPECT_NE(other_bea->roster().you, bea_number);
  // Bea's connection went quiet past two heartbeats, and she joins on a new one: the old one goes.
  bea_again->silent = 30s;
  const auto bea_third = peer(5, "10.0.0.2");
  call.join(bea_third, "bea");
  EXPECT_EQ(bea_third->roster().you, bea_number);
  ASSERT_TRUE(bea_again->closed);
  EXPECT_EQ(call.size(), 3u);
  EXPECT_FALSE(ada->closed);
}

TEST_F(CallRosterTest, BadCropsAreCountedByReasonAndAFloodClosesOnlyItsSender) {
  const auto ada = peer(1), bea = peer(2, "10.0.0.2");
  call.join(ada, "ada");
  call.join(bea, "bea");
  const protocol::Bytes not_jpeg(100, 0x42);
  for (int i = 0; i < 400 && !ada->closed; ++i) call.crop(ada->id(), protocol::FaceCrop{.jpeg = not_jpeg});
  // The rate lets a second's worth through (15), read and refused as not JPEG; the rest are too frequent.
  EXPECT_GE(counters.drops["crop-not-jpeg"], 15u);
  EXPECT_LE(counters.drops["crop-not-jpeg"], 20u);
  EXPECT_GT(counters.drops["crop-too-frequent"], 100u);
  ASSERT_TRUE(ada->closed);
  EXPECT_EQ(ada->closed->first, protocol::ErrorCode::Refused);
  EXPECT_NE(ada->closed->second.find("flooding the call"), std::string::npos) << ada->closed->second;
  // Bea sends one crop over the size limit: dropped and counted, and she stays.
  call.crop(bea->id(), protocol::FaceCrop{.jpeg = protocol::Bytes(CallOptions{}.max_crop_bytes + 1, 0xff)});
  EXPECT_EQ(counters.drops["crop-too-large"], 1u);
  EXPECT_FALSE(bea->closed);
  EXPECT_TRUE(bea->all<protocol::MemberLayers>().empty());  // nothing of Ada's was shown
}

TEST_F(CallRosterTest, AMembersFacesKeepToTheirBudgetAndTheNewestThatWaitedGoesNext) {
  const auto ada = peer(1), bea = peer(2, "10.0.0.2");
  call.join(ada, "ada");
  call.join(bea, "bea");
  const uint16_t ada_number = ada->roster().you;
  const auto face = [&](uint32_t time_ms, bool with_face) {
    CropAnalysed r{.who = {"room", ada_number}, .time_ms = time_ms, .region = protocol::FaceRegion{.found = true}};
    if (with_face) r.face = protocol::MemberLayers{.member = ada_number, .time_ms = time_ms, .yaw = int8_t(time_ms % 60), .source = protocol::FaceSource::Camera};
    return r;
  };
  // Thirty faces at once, as a burst the analyst could never send but a flood of faces could be.
  for (uint32_t t = 1; t <= 30; ++t) call.analysed(face(t, true));
  const auto shown = bea->all<protocol::MemberLayers>();
  ASSERT_GE(shown.size(), 5u);
  EXPECT_LE(shown.size(), 6u);  // a second's worth, and what the budget regained meanwhile
  for (size_t i = 0; i < shown.size(); ++i) EXPECT_EQ(shown[i].time_ms, i + 1);
  // The newest that waited goes with the member's next crop that finds room; those between were
  // replaced by it. (Crops without a face, as the analyst answers for a still face.)
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (bea->all<protocol::MemberLayers>().size() == shown.size() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(20ms);
    call.analysed(face(31, false));
  }
  const auto after = bea->all<protocol::MemberLayers>();
  ASSERT_EQ(after.size(), shown.size() + 1);
  EXPECT_EQ(after.back().time_ms, 30u);
}

}  // namespace
}  // namespace inkwire::server
