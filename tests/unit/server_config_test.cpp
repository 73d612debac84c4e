// The server's JSON config: conference sessions' face sources, and refusals with reasons.
#include <fstream>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "server/config.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::server;
namespace fs = std::filesystem;

namespace {

ServerConfig load_text(const std::string& json) {
  const fs::path file = fs::path(INKWIRE_TEST_OUTPUT_DIR) / "server-config-test.json";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << json;
  return ServerConfig::load(file);
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
