// The per-client send queue: latest wins for state, bounded for everything else (SPEC N4).
#include <gtest/gtest.h>

#include "protocol/framing.hpp"
#include "server/send_queue.hpp"

using namespace inkwire;
using namespace inkwire::protocol;
using inkwire::server::SendQueue;

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

// Voice is not a state message (every packet is different) but late voice is worth nothing: a
// reader with kMaxWaitingVoice packets waiting loses the oldest, never the connection.
TEST(SendQueueTest, LateVoiceLosesItsOldestPacketInsteadOfGrowingTheQueue) {
  SendQueue queue(1 << 20);
  for (uint8_t i = 0; i < 20; ++i)
    ASSERT_TRUE(queue.push(frame(VoiceFrame{.member = 1, .time_ms = i, .opus = Bytes(60, i)}), MessageType::VoiceFrame));
  ASSERT_TRUE(queue.push(frame(Ping{.nonce = 1}), MessageType::Ping));
  EXPECT_EQ(queue.voice_dropped(), 12u);
  const auto sent = queue.take_all();
  ASSERT_EQ(sent.size(), SendQueue::kMaxWaitingVoice + 1);
  // The newest eight are what goes out, in order, and the ping is kept.
  for (size_t i = 0; i < SendQueue::kMaxWaitingVoice; ++i) {
    const auto voice = std::get<VoiceFrame>(decode_frame(sent[i].frame->data(), sent[i].frame->size()));
    EXPECT_EQ(voice.time_ms, 12 + i);
  }
  EXPECT_EQ(sent.back().type, MessageType::Ping);
}
