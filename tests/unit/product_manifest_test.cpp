// The manifest an export writes (product.json, protocol/PRODUCT.md) for a tiny synthetic product,
// pinned in tests/golden/product-manifest.json byte for byte: the page's reader
// (client/web/net/product_manifest.js) is checked against this very file by
// client/web/test/product_manifest.test.js. A change to the C++ side fails here until the file is
// approved again (INKWIRE_APPROVE_GOLDEN=1), which the Node test then checks.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/content_hash.hpp"
#include "server/asset_store.hpp"
#include "server/products/product.hpp"
#include "server/products/product_export.hpp"
#include "server/products/product_store.hpp"
#include "test_data.hpp"

namespace inkwire {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Four views of a disc round a full turn, 32 x 24 pixels, matted, with one zoom level at twice
// the size and a pair cell between each neighbouring two: every part of a manifest, small.
Product tiny_product() {
  Product p;
  p.data.width = 32, p.data.height = 24;
  for (int i = 0; i < 4; ++i) {
    const float a = 0.5f + float(i) * 3.14159265f / 2;  // off the axes: directions of four figures
    p.data.directions.push_back({std::sin(a), 0.0f, std::cos(a)});
    Image image(32, 24, {230, 230, 230, 0});
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x)
        if ((x - 16) * (x - 16) + (y - 12) * (y - 12) < 64) {
          uint8_t* px = image.at(x, y);
          px[0] = uint8_t(60 * i + 4 * x), px[1] = uint8_t(120 + 3 * y), px[2] = uint8_t(200 - 40 * i), px[3] = 255;
        }
    p.images.push_back(image);
    const uint16_t next = uint16_t((i + 1) % 4);
    p.data.cells.push_back({.samples = {uint16_t(i), next},
                            .points = {{glm::vec2(12, 8), glm::vec2(13.5f, 8), glm::vec2(15, 8)},
                                       {glm::vec2(20, 14), glm::vec2(19.25f, 14.5f), glm::vec2(18.5f, 15)},
                                       {glm::vec2(16, 20), glm::vec2(16.5f, 20), glm::vec2(17, 20)}}});
  }
  p.matted = true;
  p.distance_diagonals = 1.6f, p.fov_y_degrees = 40.0f;
  p.levels = {{64, 48}};
  p.finer = [](size_t, const Image& first, glm::ivec2 size) { return resized(first, size.x, size.y); };
  return p;
}

fs::path exported_tiny_product() {
  const fs::path root = test::scratch_dir() / "product-manifest";
  fs::remove_all(root);
  server::AssetStore store(root / "store");
  const protocol::Snapshot state = server::store_product(store, tiny_product(), "disc");
  server::export_product(store, state, root / "export");
  return root / "export";
}

TEST(ProductManifestTest, GoldenManifestForTheWebClientIsTheseBytes) {
  const std::string manifest = read_text(exported_tiny_product() / "product.json");
  ASSERT_FALSE(manifest.empty());
  const fs::path file = fs::path(INKWIRE_GOLDEN_DIR) / "product-manifest.json";
  if (const char* approve = std::getenv("INKWIRE_APPROVE_GOLDEN"); approve && std::string(approve) == "1") {
    std::ofstream(file, std::ios::binary) << manifest;
    GTEST_SKIP() << "approved " << file;
  }
  ASSERT_TRUE(fs::exists(file)) << file << " is missing: approve it with INKWIRE_APPROVE_GOLDEN=1";
  EXPECT_EQ(read_text(file), manifest) << "the exported manifest changed: make client/web/net/product_manifest.js agree "
                                          "(node --test client/web/test/) and approve " << file;
}

// What the pinned manifest stands for, so an approved file cannot hold a wrong one: the product's
// figures, and every file it names written beside it under its own hash and size.
TEST(ProductManifestTest, TheManifestNamesEveryExportedFileByItsHashAndSize) {
  const fs::path dir = exported_tiny_product();
  const nlohmann::json m = nlohmann::json::parse(read_text(dir / "product.json"));
  EXPECT_EQ(m["format"], "inkwire-product");
  EXPECT_EQ(m["version"], 1);
  EXPECT_EQ(m["name"], "disc");
  EXPECT_EQ(m["width"], 32);
  EXPECT_EQ(m["height"], 24);
  EXPECT_NEAR(m["distance_diagonals"].get<double>(), 1.6, 1e-6);
  EXPECT_NEAR(m["fov_y_degrees"].get<double>(), 40.0, 1e-6);
  ASSERT_EQ(m["directions"].size(), 4u);
  for (const auto& d : m["directions"]) EXPECT_NEAR(std::hypot(d[0].get<double>(), d[1].get<double>(), d[2].get<double>()), 1.0, 1e-3);
  EXPECT_EQ(m["levels"], nlohmann::json::parse(R"([{"width": 64, "height": 48}])"));
  EXPECT_EQ(m["photos"].size(), 4u);
  EXPECT_EQ(m["mattes"].size(), 4u);
  ASSERT_EQ(m["zoom"].size(), 1u);
  EXPECT_EQ(m["zoom"][0].size(), 4u);
  ASSERT_EQ(m["cells"].size(), 4u);
  nlohmann::json files = nlohmann::json::array();
  for (const char* list : {"photos", "mattes", "cells"})
    for (const auto& f : m[list]) files.push_back(f);
  for (const auto& f : m["zoom"][0]) files.push_back(f);
  for (size_t i = 0; i < m["cells"].size(); ++i) EXPECT_EQ(m["cells"][i]["pair"], i);
  for (const auto& f : files) {
    const std::string name = f["file"], bytes = read_text(dir / name);
    EXPECT_EQ(bytes.size(), f["size"].get<uint64_t>()) << name;
    EXPECT_EQ(to_hex(content_hash(bytes.data(), bytes.size())), f["sha256"]) << name;
    EXPECT_NE(name.find(f["sha256"].get<std::string>()), std::string::npos) << name << " is named by its hash";
  }
}

}  // namespace
}  // namespace inkwire
