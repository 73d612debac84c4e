// Downloads that cannot race (the issue: a call client exited with "asset chunk at 0 does not
// continue the download of member-2.jpg"): two clients sharing one cache folder, and one of them
// asked for the same asset twice at once, fetch a session's assets 20 times over, each time into
// an empty folder, without an error and each with the asset's own bytes.
#include <future>

#include <gtest/gtest.h>

#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "common/content_hash.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

TEST(AssetCacheE2ETest, TwoClientsAndTwoAsksAtOnceShareOneCacheFolderWithoutARace) {
  const fs::path mesh = fs::path(INKWIRE_MESH_DIR) / "cow.off", bull = fs::path(INKWIRE_MESH_DIR) / "bull.off";
  if (!fs::exists(mesh) || !fs::exists(bull)) GTEST_SKIP() << "libcgal-demo's cow.off and bull.off are not extracted (run scripts/setup.sh)";
  const fs::path dir = output_dir("asset-cache-race");
  ServerUnderTest server(dir, {{"sessions", {{{"name", "herd"}, {"kind", "scene"}, {"assets", {{{"path", mesh.string()}}, {{"path", bull.string()}}}}}}}});
  SessionClient a(server.address(), "a"), b(server.address(), "b");
  const protocol::Snapshot snapshot = a.join("herd", "");
  b.join("herd", "");
  ASSERT_EQ(snapshot.assets.size(), 2u);
  for (int round = 0; round < 20; ++round) {
    // Both clients' caches are one folder, a fresh one each round: every fetch downloads.
    AssetCache for_a(dir / ("cache-" + std::to_string(round))), for_b(dir / ("cache-" + std::to_string(round)));
    std::vector<std::future<fs::path>> fetches;
    for (const auto& asset : snapshot.assets) {
      fetches.push_back(std::async(std::launch::async, [&, asset] { return a.fetch_asset(asset, for_a); }));
      fetches.push_back(std::async(std::launch::async, [&, asset] { return a.fetch_asset(asset, for_a); }));  // the same ask again, at once
      fetches.push_back(std::async(std::launch::async, [&, asset] { return b.fetch_asset(asset, for_b); }));
    }
    for (size_t i = 0; i < fetches.size(); ++i) {
      const protocol::AssetAnnounce& asset = snapshot.assets[i / 3];
      fs::path got;
      ASSERT_NO_THROW(got = fetches[i].get()) << "round " << round << ", fetch " << i;
      EXPECT_EQ(content_hash_of_file(got), asset.hash) << "round " << round << ": " << got;
    }
    for (const auto& entry : fs::directory_iterator(dir / ("cache-" + std::to_string(round))))
      EXPECT_NE(entry.path().extension(), ".partial") << "a partial file is left: " << entry.path();
  }
}
