// What a public server needs (SPEC D3), end to end on 127.0.0.1: wrong tokens guessed many times
// in a row are slowed down while the right token still works; connections past the cap per
// address are refused with the reason; a stored asset corrupted on disk is refused, not served,
// while the server carries on; tokens are never stored as they are.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "common/content_hash.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
namespace fs = std::filesystem;

namespace {

const fs::path kMesh = fs::path(INKWIRE_MESH_DIR) / "cow.off";

// The test's clients are on this machine: the per-address limits are asked to apply to it.
nlohmann::json config(nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json c = {{"limit_loopback", true}, {"sessions", {{{"name", "cows"}, {"kind", "scene"}, {"assets", {{{"path", kMesh.string()}}}}},
                                    {{"name", "locked"}, {"kind", "scene"}, {"token", "s3cret"}, {"assets", nlohmann::json::array()}}}}};
  c.update(extra);
  return c;
}

// Seconds one join with `token` takes from a fresh connection, and whether it was let in.
std::pair<double, bool> timed_join(const ServerUnderTest& server, const std::string& token) {
  SessionClient client(server.address(), "guesser");
  const auto start = std::chrono::steady_clock::now();
  bool in = true;
  try {
    client.join("locked", token);
  } catch (const Error&) {
    in = false;
  }
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), in};
}

}  // namespace

class HardeningE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kMesh)) GTEST_SKIP() << "libcgal-demo's cow.off is not extracted (run scripts/setup.sh)";
  }
};

TEST_F(HardeningE2ETest, WrongTokensInARowAreSlowedDownAndTheRightOneStillWorks) {
  const fs::path dir = output_dir("token-guessing");
  ServerUnderTest server(dir, config({{"join_failures_allowed", 3}}));
  // What the server slowed, from its log ("join-slowed" with the wait it put before the join):
  // the waits it chose, not the clock's, so a loaded machine cannot make one look longer.
  const auto slowed = [&] {
    std::vector<int64_t> delays;
    for (const auto& j : log_events(server.process().output(), "join-slowed")) delays.push_back(j.value("delay_ms", int64_t(0)));
    return delays;
  };
  // The first few mistakes cost nothing (a person mistyping).
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(timed_join(server, "guess" + std::to_string(i)).second);
  EXPECT_TRUE(slowed().empty()) << "the first mistakes were slowed down";
  // Then every further join from this address waits longer: 0.25 s, 0.5 s, 1 s; and the join
  // takes at least that long (the lower bound holds however busy the machine is).
  for (int i = 0; i < 3; ++i) {
    const auto [seconds, in] = timed_join(server, "guess-more" + std::to_string(i));
    EXPECT_FALSE(in);
    ASSERT_EQ(slowed().size(), size_t(i + 1)) << "guess " << i + 4 << " was not slowed down";
    EXPECT_EQ(slowed().back(), 250 << i) << "guess " << i + 4;
    EXPECT_GE(seconds, 0.25 * (1 << i) * 0.9) << "guess " << i + 4 << " did not wait";
  }
  // The right token is let in (after the same wait), and clears the count: the next join waits for nothing.
  EXPECT_TRUE(timed_join(server, "s3cret").second);
  ASSERT_EQ(slowed().size(), 4u);
  EXPECT_EQ(slowed().back(), 2000);
  EXPECT_TRUE(timed_join(server, "s3cret").second);
  EXPECT_EQ(slowed().size(), 4u) << "a right token did not clear the slow-down";
  // Meanwhile other clients are served at once.
  SessionClient other(server.address(), "other");
  EXPECT_NO_THROW(other.join("cows", ""));
}

TEST_F(HardeningE2ETest, TokensAreStoredAsDigestsNeverAsTheyAre) {
  const fs::path dir = output_dir("token-digest");
  { ServerUnderTest server(dir, config()); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2((dir / "data" / "catalogue.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT token FROM sessions WHERE name = 'locked'", -1, &q, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(q), SQLITE_ROW);
  const std::string stored = reinterpret_cast<const char*>(sqlite3_column_text(q, 0));
  sqlite3_finalize(q);
  sqlite3_close(db);
  EXPECT_EQ(stored.find("s3cret"), std::string::npos);
  EXPECT_EQ(stored, "sha256:" + to_hex(content_hash("s3cret", 6)));
}

TEST_F(HardeningE2ETest, ConnectionsPastTheCapPerAddressAreRefusedWithTheReason) {
  const fs::path dir = output_dir("connection-cap");
  ServerUnderTest server(dir, config({{"max_connections_per_address", 3}}));
  std::vector<std::unique_ptr<SessionClient>> allowed;
  for (int i = 0; i < 3; ++i) {
    allowed.push_back(std::make_unique<SessionClient>(server.address(), "c" + std::to_string(i)));
    allowed.back()->join("cows", "");
  }
  try {
    SessionClient fourth(server.address(), "fourth");
    fourth.join("cows", "");
    ADD_FAILURE() << "a fourth connection from one address was served";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("too many connections"), std::string::npos) << e.what();
  }
  // The three are still served, and a place frees when one leaves.
  allowed.front()->send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  EXPECT_TRUE(eventually([&] { return allowed.back()->state().style.renderer == "comic"; }));
  allowed.erase(allowed.begin());
  EXPECT_TRUE(eventually([&] {
    try {
      SessionClient again(server.address(), "again");
      again.join("cows", "");
      return true;
    } catch (const Error&) {
      return false;
    }
  }));
}

TEST_F(HardeningE2ETest, HttpRequestsCountAgainstTheCapSoHeldHeadsCannotExhaustTheServer) {
  const fs::path dir = output_dir("http-cap");
  ServerUnderTest server(dir, config({{"max_connections_per_address", 3}, {"http", "127.0.0.1:0"}, {"http_head_timeout_seconds", 1.0}}));
  const int port = http_port(server);
  // Three connections that never finish their request head hold the address's places...
  asio::io_context io;
  std::vector<asio::ip::tcp::socket> held;
  for (int i = 0; i < 3; ++i) {
    held.emplace_back(io);
    held.back().connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
    asio::write(held.back(), asio::buffer(std::string("GET / HTTP/1.1\r\n")));
  }
  // (wait until the server has accepted all three)
  ASSERT_TRUE(eventually([&] { return http_get(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n").find("503") != std::string::npos; }));
  // ... so a fourth request from it is refused at once, saying why,
  const std::string refused = http_get(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_NE(refused.find("503"), std::string::npos) << refused;
  EXPECT_NE(refused.find("too many connections"), std::string::npos) << refused;
  // ... until the head timeout cuts the three off and gives their places back.
  EXPECT_TRUE(eventually([&] { return http_get(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK") != std::string::npos; }, std::chrono::seconds(60)));
}

TEST_F(HardeningE2ETest, AnAssetCorruptedOnDiskIsRefusedNotServed) {
  const fs::path dir = output_dir("corrupted-asset");
  ServerUnderTest server(dir, config());
  SessionClient client(server.address(), "client");
  const protocol::Snapshot state = client.join("cows", "");
  ASSERT_EQ(state.assets.size(), 1u);
  // One byte of the stored mesh changes under the running server (a failing disk, a meddler).
  const fs::path stored = dir / "data" / "assets" / to_hex(state.assets[0].hash);
  ASSERT_TRUE(fs::exists(stored));
  {
    std::fstream f(stored, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('#');
  }
  AssetCache cache(dir / "cache");
  try {
    client.fetch_asset(state.assets[0], cache);
    ADD_FAILURE() << "a corrupted asset was served";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not match its hash"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(log_events(server.process().output(), "asset-corrupted").empty()) << server.process().output();
  SessionClient other(server.address(), "other");
  EXPECT_NO_THROW(other.join("cows", "")) << "the server stopped serving after a corrupted asset";
}

TEST_F(HardeningE2ETest, ThisMachinesOwnAddressIsNotCappedUnlessAsked) {
  // A proxy on the server's own machine speaks for many people from 127.0.0.1.
  const fs::path dir = output_dir("loopback-uncapped");
  nlohmann::json c = config({{"max_connections_per_address", 3}});
  c.erase("limit_loopback");
  ServerUnderTest server(dir, c);
  std::vector<std::unique_ptr<SessionClient>> clients;
  for (int i = 0; i < 5; ++i) {
    clients.push_back(std::make_unique<SessionClient>(server.address(), "c" + std::to_string(i)));
    EXPECT_NO_THROW(clients.back()->join("cows", "")) << "connection " << i + 1;
  }
}
