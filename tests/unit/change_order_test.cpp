// The order in which a session's changes from the broker are applied (server/relay/change_order.hpp):
// one after another by revision, a gap asks for a resync and what comes meanwhile waits for it,
// bounded. No broker and no socket: the relay's decisions alone.
#include "server/relay/change_order.hpp"

#include <gtest/gtest.h>

#include "tests/unit/open_sockets.hpp"

namespace inkwire::server {
namespace {

BrokerEvent change(uint32_t revision) {
  return {.revision = revision, .origin = "a", .session = "s", .change = protocol::StyleChange{.renderer = "comic"}};
}

std::vector<uint32_t> revisions(const std::vector<BrokerEvent>& events) {
  std::vector<uint32_t> out;
  for (const auto& e : events) out.push_back(e.revision);
  return out;
}

class ChangeOrderTest : public ::testing::Test {
 protected:
  void TearDown() override { EXPECT_EQ(test::open_sockets(), 0) << "the relay's ordering is decided without a socket"; }
};

TEST_F(ChangeOrderTest, ChangesInOrderApplyAtOnceAndOnesAlreadyHeldAreSkipped) {
  ChangeOrder order;
  for (uint32_t r = 1; r <= 3; ++r) {
    const auto a = order.arrive(change(r));
    ASSERT_TRUE(a.apply);
    EXPECT_EQ(a.apply->revision, r);
    EXPECT_FALSE(a.resync);
  }
  EXPECT_EQ(order.revision(), 3u);
  const auto again = order.arrive(change(2));
  EXPECT_FALSE(again.apply);
  EXPECT_FALSE(again.resync);
  EXPECT_EQ(order.revision(), 3u);
}

TEST_F(ChangeOrderTest, AGapAsksForAResyncAndWhatWaitedAppliesAfterItInRevisionOrder) {
  ChangeOrder order;
  ASSERT_TRUE(order.arrive(change(1)).apply);
  const auto gap = order.arrive(change(4));  // 2 and 3 were missed
  EXPECT_FALSE(gap.apply);
  EXPECT_TRUE(gap.resync);
  order.resync_started();
  // Meanwhile, out of order and one already in the state the resync will read.
  for (uint32_t r : {6u, 5u, 3u}) {
    const auto a = order.arrive(change(r));
    EXPECT_FALSE(a.apply) << r;
    EXPECT_FALSE(a.resync) << r;
  }
  const auto done = order.resynced(3);  // the state read holds everything up to 3
  EXPECT_EQ(revisions(done.apply), (std::vector<uint32_t>{4, 5, 6}));
  EXPECT_FALSE(done.resync);
  EXPECT_FALSE(order.syncing());
  EXPECT_EQ(order.revision(), 6u);
  EXPECT_TRUE(order.arrive(change(7)).apply);
}

TEST_F(ChangeOrderTest, AGapAmongWhatWaitedAsksForAnotherResyncAndKeepsWhatIsBehindIt) {
  ChangeOrder order;
  ASSERT_TRUE(order.arrive(change(2)).resync);  // the first heard is 2: 1 was missed
  order.resync_started();
  for (uint32_t r : {3u, 5u, 6u}) order.arrive(change(r));
  const auto first = order.resynced(2);
  EXPECT_EQ(revisions(first.apply), (std::vector<uint32_t>{3}));
  EXPECT_TRUE(first.resync);  // 4 is missing
  order.resync_started();
  const auto second = order.resynced(4);
  EXPECT_EQ(revisions(second.apply), (std::vector<uint32_t>{5, 6}));
  EXPECT_FALSE(second.resync);
}

TEST_F(ChangeOrderTest, WaitingIsBoundedAndTheOverflowIsSaid) {
  ChangeOrder order;
  order.resync_started();
  size_t dropped = 0;
  for (uint32_t r = 1; r <= ChangeOrder::kMaxWaiting + 5; ++r) dropped += order.arrive(change(r)).dropped;
  EXPECT_EQ(dropped, ChangeOrder::kMaxWaiting);  // once, all that waited
  const auto done = order.resynced(ChangeOrder::kMaxWaiting + 2);
  EXPECT_EQ(revisions(done.apply), (std::vector<uint32_t>{ChangeOrder::kMaxWaiting + 3, ChangeOrder::kMaxWaiting + 4, ChangeOrder::kMaxWaiting + 5}));
}

TEST_F(ChangeOrderTest, ABrokerLostDropsWhatWaitedForTheReconnectionsResync) {
  ChangeOrder order;
  ASSERT_TRUE(order.arrive(change(1)).apply);
  ASSERT_TRUE(order.arrive(change(3)).resync);
  order.resync_started();
  order.arrive(change(4));
  order.broker_lost();
  EXPECT_FALSE(order.syncing());
  order.resync_started();  // the reconnection reads every session whole
  const auto done = order.resynced(9);
  EXPECT_TRUE(done.apply.empty());
  EXPECT_EQ(order.revision(), 9u);
  EXPECT_FALSE(order.arrive(change(9)).apply);
  EXPECT_TRUE(order.arrive(change(10)).apply);
}

}  // namespace
}  // namespace inkwire::server
