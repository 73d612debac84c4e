// The per-client send queue: latest wins for state, bounded for everything else (SPEC N4).
#include <gtest/gtest.h>

#include "protocol/framing.hpp"
#include "server/send_queue.hpp"

using namespace inkwire;
using namespace inkwire::protocol;

namespace {
std::shared_ptr<const Bytes> frame(const Message& m) { return std::make_shared<const Bytes>(encode(m)); }
}  // namespace

TEST(SendQueueTest, StateMessagesReplaceTheirQueuedPredecessorInPlace) {
  server::SendQueue q(1 << 20);
  q.push(frame(CameraPose{.sequence = 1}), MessageType::CameraPose);
  q.push(frame(AssetChunk{}), MessageType::AssetChunk);
  q.push(frame(CameraPose{.sequence = 2}), MessageType::CameraPose);
  q.push(frame(StyleChange{}), MessageType::StyleChange);
  EXPECT_EQ(q.replaced(), 1u);
  const auto all = q.take_all();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].type, MessageType::CameraPose);
  const auto& f = *all[0].frame;
  EXPECT_EQ(std::get<CameraPose>(decode(MessageType::CameraPose, f.data() + kHeaderBytes, f.size() - kHeaderBytes)).sequence, 2u);
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.bytes(), 0u);
}

TEST(SendQueueTest, OtherMessagesAreNeverDroppedButOverflowIsReported) {
  const auto chunk = frame(AssetChunk{.hash = {}, .offset = 0, .data = Bytes(1000)});
  server::SendQueue q(3 * chunk->size());
  EXPECT_TRUE(q.push(chunk, MessageType::AssetChunk));
  EXPECT_TRUE(q.push(chunk, MessageType::AssetChunk));
  EXPECT_TRUE(q.push(chunk, MessageType::AssetChunk));
  EXPECT_FALSE(q.push(chunk, MessageType::AssetChunk));
  // State still gets through a full queue: at most one per type is ever held.
  EXPECT_TRUE(q.push(frame(CameraPose{}), MessageType::CameraPose));
  EXPECT_TRUE(q.push(frame(CameraPose{}), MessageType::CameraPose));
  EXPECT_EQ(q.take_all().size(), 4u);
}
