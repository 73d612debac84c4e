// The server's JSON config: conference sessions' face sources, and refusals with reasons.

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "server/config.hpp"
#include "server/relay/redis_relay.hpp"
#include "server/session_token.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::server;
namespace fs = std::filesystem;

namespace {

ServerConfig load_text(const std::string& json) {
  return ServerConfig::load(test::write_temp("server-config.json", json));
}

std::string refusal(const std::string& json) {
  return test::error_of([&] { load_text(json); });
}

}  // namespace

TEST(ServerConfigTest, AConferenceTakesAFaceSourceWithDefaults) {
  const ServerConfig c = load_text(R"({"sessions": [
      {"name": "meeting", "kind": "conference", "face": {"source": "camera:0"}},
      {"name": "recorded", "kind": "conference", "face": {"source": "talk.mp4", "neutral": "me.jpg", "loop": false, "fps": 15}},
      {"name": "plain", "kind": "conference"}]})");
  ASSERT_EQ(c.sessions.size(), 3u);
  ASSERT_TRUE(c.sessions[0].face);
  EXPECT_EQ(c.sessions[0].face->source, "camera:0");
  EXPECT_TRUE(c.sessions[0].face->neutral.empty());
  EXPECT_TRUE(c.sessions[0].face->loop);
  EXPECT_EQ(c.sessions[0].face->fps, 0.0);
  ASSERT_TRUE(c.sessions[1].face);
  EXPECT_EQ(c.sessions[1].face->neutral, "me.jpg");
  EXPECT_FALSE(c.sessions[1].face->loop);
  EXPECT_EQ(c.sessions[1].face->fps, 15.0);
  EXPECT_FALSE(c.sessions[2].face);
}

TEST(ServerConfigTest, FaceSourcesOutsideConferencesOrWithoutASourceAreRefused) {
  EXPECT_NE(refusal(R"({"sessions": [{"name": "s", "kind": "scene", "face": {"source": "camera:0"}}]})").find("only conference sessions"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"sessions": [{"name": "c", "kind": "conference", "face": {"neutral": "me.jpg"}}]})").find("source"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"sessions": [{"name": "c", "kind": "conference", "face": {"source": ""}}]})").find("empty"), std::string::npos);
  EXPECT_NE(refusal(R"({"sessions": [{"name": "c", "kind": "conference", "face": {"source": "x", "fps": 1000}}]})").find("fps"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"sessions": [{"name": "c", "kind": "conference", "face": {"source": 7}}]})"), "");
  EXPECT_NE(refusal(R"({"sessions": [{"name": "c", "kind": "conference", "face": )"), "");
}

TEST(ServerConfigTest, SeveralInstancesNameTheirBrokerAndLimitsAreRead) {
  const ServerConfig c = load_text(R"({"name": "shop-1", "broker": "redis://10.0.0.5:6380",
      "max_connections": 100, "max_connections_per_address": 4, "join_failures_allowed": 0})");
  EXPECT_EQ(c.name, "shop-1");
  EXPECT_EQ(c.broker, "redis://10.0.0.5:6380");
  EXPECT_EQ(c.max_connections, 100u);
  EXPECT_EQ(c.max_connections_per_address, 4u);
  EXPECT_EQ(c.join_failures_allowed, 0);
  EXPECT_TRUE(ServerConfig::embedded_default().broker.empty()) << "one instance without a broker stays the default";
  EXPECT_NE(refusal(R"({"max_connections_per_address": 0})").find("max_connections"), std::string::npos);
  EXPECT_NE(refusal(R"({"join_failures_allowed": -1})").find("join_failures_allowed"), std::string::npos);
}

TEST(ServerConfigTest, BrokerAddressesAreReadOrRefusedWithTheReason) {
  const BrokerAddress a = parse_broker("redis://127.0.0.1:6390");
  EXPECT_EQ(a.host, "127.0.0.1");
  EXPECT_EQ(a.port, 6390);
  EXPECT_EQ(parse_broker("redis://cache.internal").port, 6379) << "Redis' own port when none is given";
  const BrokerAddress secret = parse_broker("redis://:pa:ss@word@10.0.0.5:6380");
  EXPECT_EQ(secret.password, "pa:ss@word");
  EXPECT_EQ(secret.user, "");
  EXPECT_EQ(secret.host, "10.0.0.5");
  EXPECT_EQ(parse_broker("redis://inkwire:pw@h").user, "inkwire");
  const auto refused = [](const std::string& url) { return test::error_of([&] { parse_broker(url); }); };
  EXPECT_NE(refused("nats://127.0.0.1:4222").find("this build relays through Redis"), std::string::npos);
  EXPECT_NE(refused("http://127.0.0.1:6379").find("is not redis://"), std::string::npos);
  EXPECT_NE(refused("redis://127.0.0.1:99999").find("port"), std::string::npos);
  EXPECT_NE(refused("redis://127.0.0.1:").find("port"), std::string::npos);
  EXPECT_NE(refused("redis://:6379").find("no host"), std::string::npos);
  EXPECT_NE(refused("redis://secret@h:6379").find("credentials"), std::string::npos);
}

TEST(SessionTokenTest, TokensAreKeptAsDigestsAndCompared) {
  const std::string stored = hash_token("s3cret");
  EXPECT_EQ(stored.rfind("sha256:", 0), 0u);
  EXPECT_EQ(stored.find("s3cret"), std::string::npos);
  EXPECT_TRUE(token_matches(stored, "s3cret"));
  EXPECT_FALSE(token_matches(stored, "s3cre"));
  EXPECT_FALSE(token_matches(stored, "s3cret "));
  EXPECT_FALSE(token_matches(stored, ""));
  EXPECT_FALSE(token_matches(stored, stored)) << "the digest itself is no token";
  EXPECT_TRUE(token_matches("", "anything")) << "a session without a token is open";
  EXPECT_TRUE(hash_token("").empty());
  // A catalogue of an older version kept tokens as they are: read as digests of them.
  EXPECT_EQ(as_token_hash("s3cret"), stored);
  EXPECT_EQ(as_token_hash(stored), stored);
}
