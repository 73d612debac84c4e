// What instances write into the broker and read back (server/relay/broker_formats): changes and
// session definitions go there and back unchanged; anything else is refused with a reason, never
// read past its end.
#include <gtest/gtest.h>

#include "protocol/framing.hpp"
#include "server/relay/broker_formats.hpp"
#include "server/session_token.hpp"

using namespace inkwire;
using namespace inkwire::server;

namespace {

std::string text_of(const protocol::Bytes& frame) { return std::string(frame.begin(), frame.end()); }

std::string published(uint32_t revision, const std::string& origin, const std::string& session, const protocol::Message& change) {
  return std::to_string(revision) + " " + event_header(1764000000000000, 42, origin, session) + text_of(protocol::encode(change));
}

}  // namespace

TEST(BrokerFormatsTest, AChangeComesBackAsItWasPublished) {
  const protocol::StyleChange style{.renderer = "comic", .settings = {"shade_map=metal"}};
  // Names may hold the separators themselves: they are counted, not delimited.
  const BrokerEvent e = parse_event(published(7, "shop 1:a", "cows: the herd", style));
  EXPECT_EQ(e.revision, 7u);
  EXPECT_EQ(e.published_us, 1764000000000000);
  EXPECT_EQ(e.sender, 42u);
  EXPECT_EQ(e.origin, "shop 1:a");
  EXPECT_EQ(e.session, "cows: the herd");
  EXPECT_EQ(std::get<protocol::StyleChange>(e.change), style);
  EXPECT_EQ(state_field(e.change), "style");
}

TEST(BrokerFormatsTest, ASessionDefinitionComesBackWhole) {
  StoredSession s{.token = hash_token("s3cret"), .editor_token = hash_token("ed1tor"), .state = {}};
  s.state.session = "cows";
  s.state.revision = 9;
  s.state.assets.push_back({.hash = {}, .size = 10, .kind = protocol::AssetKind::Mesh, .name = "cow.off"});
  const StoredSession back = parse_session_definition(session_definition(s));
  EXPECT_EQ(back.token, s.token);
  EXPECT_EQ(back.editor_token, s.editor_token);
  EXPECT_EQ(back.state, s.state);
}

TEST(BrokerFormatsTest, AnythingElseIsRefusedWithAReason) {
  const std::string good = published(7, "a", "cows", protocol::CameraPose{});
  const auto refusal = [](const std::string& text) {
    try {
      parse_event(text);
    } catch (const protocol::ProtocolError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal(good), "");
  // Every truncation of a good text is refused, never read past its end.
  for (size_t n = 0; n < good.size(); ++n) EXPECT_NE(refusal(good.substr(0, n)), "") << "cut at " << n;
  EXPECT_NE(refusal("7 1 2 9999:a4:cows"), "");                  // a name longer than what is left
  EXPECT_NE(refusal("x 1 2 1:a4:cows"), "");                     // no revision
  EXPECT_NE(refusal("99999999999 1 2 1:a4:cows"), "");           // a revision past 32 bits
  EXPECT_NE(refusal(published(7, "a", "cows", protocol::Ping{})).find("not session state"), std::string::npos);
  EXPECT_THROW(parse_session_definition("3:abc" + text_of(protocol::encode(protocol::Ping{}))), protocol::ProtocolError);
}

// A call's traffic between instances: a voice frame, a face, a roster (with its room's host and
// lock), a photo and a room's removal of a member come back as they went; a message a call does
// not share, a truncated photo or removal are refused.
TEST(BrokerFormatsTest, ACallsShareComesBackAsItWentAndOtherMessagesAreRefused) {
  const std::vector<CallShare> shares = {
      {.origin = "one", .session = "call", .message = protocol::VoiceFrame{.member = 3, .time_ms = 120, .opus = protocol::Bytes(40, 7)}},
      {.origin = "one", .session = "call", .message = protocol::MemberFace{.member = 3, .time_ms = 140, .yaw = -9}},
      {.origin = "one", .session = "call", .message = protocol::Roster{.you = 0, .members = {protocol::CallMember{.member = 3, .name = "Ada"}}}},
      {.origin = "one", .session = "call", .photo_member = 3, .photo = protocol::Bytes(5000, 0xd8), .landmarks = "{\"points\": []}"},
      {.origin = "one", .session = "call", .message = protocol::Roster{.you = 0, .members = {protocol::CallMember{.member = 3, .name = "Ada"}}, .host = 3, .locked = true}},
      {.origin = "one", .session = "call", .removal = CallShare::Removal{.instance = "two", .member = 5, .reason = "the host removed you from room call"}}};
  for (const CallShare& s : shares) {
    const CallShare back = parse_call_share(call_share(s));
    EXPECT_EQ(back.origin, s.origin);
    EXPECT_EQ(back.session, s.session);
    EXPECT_EQ(back.message, s.message);
    EXPECT_EQ(back.photo_member, s.photo_member);
    EXPECT_EQ(back.photo, s.photo);
    EXPECT_EQ(back.landmarks, s.landmarks);
    EXPECT_EQ(back.removal, s.removal);
  }
  const std::string removal = call_share(shares[5]);
  for (size_t cut : {size_t(1), size_t(10), removal.size() - 1}) EXPECT_THROW(parse_call_share(removal.substr(0, cut)), protocol::ProtocolError) << cut;
  EXPECT_THROW(parse_call_share("R3:one4:call3:two0 2:no"), protocol::ProtocolError) << "member 0";
  EXPECT_THROW(parse_call_share(call_share({.origin = "one", .session = "call", .message = protocol::StyleChange{}})), protocol::ProtocolError);
  const std::string photo = call_share(shares[3]);
  for (size_t cut : {size_t(1), size_t(10), photo.size() / 2, photo.size() - 1}) EXPECT_THROW(parse_call_share(photo.substr(0, cut)), protocol::ProtocolError) << cut;
}
