// A minute of the soak (SPEC D8): `inkwire-bench --suite soak --minutes 1` runs two real
// inkwire-server processes on a real redis-server under churn (joins, leaves, silent call
// members, products added and removed, a broker restart, an instance killed); afterwards no
// ghost member, nothing acknowledged lost, and the first instance's descriptors and memory back
// within 10% of the start. The hour-long run is the bench's (docs/benchmarks.md). Skipped with a
// message without redis-server or inkwire-bench.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "e2e_support.hpp"

using namespace inkwire::e2e;
namespace fs = std::filesystem;

TEST(SoakE2ETest, AMinuteOfChurnLeavesNoGhostLosesNothingAcknowledgedAndGivesBackDescriptorsAndMemory) {
  if (!fs::exists("/usr/bin/redis-server")) GTEST_SKIP() << "redis-server is missing (Debian package redis-server)";
  if (!fs::exists(fs::path(INKWIRE_BIN_DIR) / "inkwire-bench")) GTEST_SKIP() << "inkwire-bench is not built (INKWIRE_BUILD_BENCH)";
  const fs::path dir = output_dir("soak");
  Process bench("inkwire-bench", {"--suite", "soak", "--minutes", "1", "--json", (dir / "soak.json").string()}, dir / "bench.log");
  ASSERT_EQ(bench.wait(std::chrono::minutes(5)), 0) << bench.output();
  const nlohmann::json row = nlohmann::json::parse(std::ifstream(dir / "soak.json"))["results"].at(0);
  const nlohmann::json& c = row["counters"];
  std::printf("%s\n", c.dump().c_str());
  EXPECT_EQ(c["ghost_members"], 0) << bench.output();
  EXPECT_EQ(c["lost_acknowledged"], 0) << bench.output();
  EXPECT_EQ(c["removed_products_served"], 0);
  // The churn happened: every kind of event, and the steady traffic went through.
  EXPECT_GE(c["visitors_joined"].get<double>(), 200);
  EXPECT_GE(c["call_members_silent"].get<double>(), 5);
  EXPECT_GE(c["products_removed"].get<double>(), 1);
  EXPECT_EQ(c["broker_restarts"], 1);
  EXPECT_EQ(c["instance_kills"], 1);
  EXPECT_GT(c["delivered_fraction"].get<double>(), 0.9);
  EXPECT_LE(c["fds_end"].get<double>(), c["fds_start"].get<double>() * 1.1);
  EXPECT_LE(c["rss_mb_end"].get<double>(), c["rss_mb_start"].get<double>() * 1.1);
}
