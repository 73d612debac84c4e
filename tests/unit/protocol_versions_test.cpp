// Older peers' wire (protocol/versions.hpp): what a peer of version 7 or 8 is sent and how what
// it writes is read, byte for byte as its own version's codec has it.
#include <gtest/gtest.h>

#include "protocol/framing.hpp"
#include "protocol/versions.hpp"

using namespace inkwire::protocol;

namespace {

std::shared_ptr<const Bytes> frame_of(const Message& m) { return std::make_shared<const Bytes>(encode(m)); }

Roster a_room_roster() {
  return {.you = 2, .members = {{.member = 1, .name = "Ada"}, {.member = 2, .name = "Bea"}}, .host = 1, .locked = true};
}

}  // namespace

TEST(ProtocolVersionsTest, APeerOfThisVersionGetsEveryFrameAsItIs) {
  for (const Message& m : {Message(a_room_roster()), Message(HostKey{.key = std::string(32, 'a')}), Message(MemberLayers{.member = 1}),
                           Message(ErrorMessage{.code = ErrorCode::Locked, .reason = "room r is locked"})}) {
    const auto frame = frame_of(m);
    EXPECT_EQ(frame_for(kVersion, frame, type_of(m)), frame) << name_of(type_of(m));
  }
}

TEST(ProtocolVersionsTest, TypesNewerThanThePeerAreNotSent) {
  EXPECT_EQ(message_types_of(7), 27);
  EXPECT_EQ(message_types_of(8), 29);
  EXPECT_EQ(message_types_of(kVersion), kMessageTypes);
  EXPECT_EQ(frame_for(8, frame_of(MemberLayers{.member = 1}), MessageType::MemberLayers), nullptr);
  EXPECT_EQ(frame_for(7, frame_of(MemberLayers{.member = 1}), MessageType::MemberLayers), nullptr);
  EXPECT_EQ(frame_for(7, frame_of(HostKey{.key = std::string(32, 'a')}), MessageType::HostKey), nullptr);
  const auto key = frame_of(HostKey{.key = std::string(32, 'a')});
  EXPECT_EQ(frame_for(8, key, MessageType::HostKey), key);
  const auto face = frame_of(MemberFace{.member = 1});
  EXPECT_EQ(frame_for(7, face, MessageType::MemberFace), face);
}

// Version 7's roster: you, members, and nothing after them.
TEST(ProtocolVersionsTest, AVersion7PeersRosterHasNoHostOrLock) {
  const Roster roster = a_room_roster();
  const auto full = frame_of(roster);
  EXPECT_EQ(frame_for(8, full, MessageType::Roster), full);
  const auto older = frame_for(7, full, MessageType::Roster);
  ASSERT_NE(older, nullptr);
  ASSERT_EQ(older->size(), full->size() - 3);
  const FrameHeader h = parse_header(older->data());
  EXPECT_EQ(h.type, MessageType::Roster);
  EXPECT_EQ(h.length, older->size() - kHeaderBytes);
  // Its bytes are this version's roster of the same members without a host, less the host and lock.
  Roster hostless = roster;
  hostless.host = 0, hostless.locked = false;
  const Bytes expected = encode(hostless);
  EXPECT_TRUE(std::equal(older->begin() + kHeaderBytes, older->end(), expected.begin() + kHeaderBytes));
  EXPECT_THROW(decode_frame(older->data(), older->size()), ProtocolError) << "this version's reader wants host and locked";
}

TEST(ProtocolVersionsTest, AVersion7PeerIsToldLockedOrRemovedAsRefused) {
  for (const ErrorCode code : {ErrorCode::Locked, ErrorCode::Removed}) {
    const auto frame = frame_of(ErrorMessage{.code = code, .reason = "room r is locked: ask Ada (its host) to open it"});
    EXPECT_EQ(frame_for(8, frame, MessageType::Error), frame);
    const auto older = frame_for(7, frame, MessageType::Error);
    ASSERT_NE(older, nullptr);
    const auto error = std::get<ErrorMessage>(decode_frame(older->data(), older->size()));
    EXPECT_EQ(error.code, ErrorCode::Refused);
    EXPECT_EQ(error.reason, "room r is locked: ask Ada (its host) to open it");
  }
  const auto slow = frame_of(ErrorMessage{.code = ErrorCode::TooSlow, .reason = "slow"});
  EXPECT_EQ(frame_for(7, slow, MessageType::Error), slow);
}

TEST(ProtocolVersionsTest, AVersion7JoinIsReadWithoutOpenRoom) {
  const Bytes now = encode(Join{.session = "call", .token = "t0ken", .open_room = true});
  // Version 7 wrote the session and the token only.
  const Bytes older(now.begin() + kHeaderBytes, now.end() - 1);
  const auto join = std::get<Join>(decode_from(7, MessageType::Join, older.data(), older.size()));
  EXPECT_EQ(join, (Join{.session = "call", .token = "t0ken", .open_room = false}));
  EXPECT_THROW(decode_from(7, MessageType::Join, now.data() + kHeaderBytes, now.size() - kHeaderBytes), ProtocolError)
      << "a version-7 join has no open_room byte";
  EXPECT_THROW(decode_from(8, MessageType::Join, older.data(), older.size()), ProtocolError) << "a version-8 join has it";
  EXPECT_EQ(std::get<Join>(decode_from(8, MessageType::Join, now.data() + kHeaderBytes, now.size() - kHeaderBytes)).open_room, true);
}

TEST(ProtocolVersionsTest, APeerMaySendOnlyItsVersionsTypes) {
  const Bytes control = encode(RoomControl{.action = RoomAction::Lock, .member = 0});
  EXPECT_THROW(decode_from(7, MessageType::RoomControl, control.data() + kHeaderBytes, control.size() - kHeaderBytes), ProtocolError);
  EXPECT_NO_THROW(decode_from(8, MessageType::RoomControl, control.data() + kHeaderBytes, control.size() - kHeaderBytes));
  const Bytes layers = encode(MemberLayers{.member = 1});
  EXPECT_THROW(decode_from(8, MessageType::MemberLayers, layers.data() + kHeaderBytes, layers.size() - kHeaderBytes), ProtocolError);
}
