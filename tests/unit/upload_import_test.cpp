// An uploaded model made into the scene's one GLB and checked (server/making/upload_import.hpp),
// in this process: a textured glTF with its files, a model reaching outside its upload, one over
// the triangle cap, a texture claiming too many pixels (refused from its header, never decoded).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <zlib.h>

#include "common/model_files.hpp"
#include "server/making/upload_import.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::server;
namespace fs = std::filesystem;

namespace {

const fs::path kBox = test::kAssimpModels / "glTF2/BoxTextured-glTF";

// A fresh upload folder holding the box's three files.
fs::path box_upload() {
  const fs::path folder = test::scratch_dir() / "upload";
  fs::remove_all(folder);
  fs::create_directories(folder);
  for (const char* f : {"BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png"}) fs::copy_file(kBox / f, folder / f);
  return folder;
}

void replace_in(const fs::path& file, const std::string& from, const std::string& to) {
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  std::ofstream(file) << text;
}

}  // namespace

TEST(UploadImportTest, ATexturedGltfWithItsFilesBecomesOneGlb) {
  INKWIRE_REQUIRE_FILE(kBox / "BoxTextured.gltf");
  const fs::path folder = box_upload();
  confine_model_files(folder);
  const ImportedModel model = import_upload(folder, {});
  EXPECT_EQ(model.name, "BoxTextured.glb");
  EXPECT_EQ(model.triangles, 12u);
  EXPECT_EQ(model.texture_pixels, 211u * 211u) << "the logo's pixels, read from its header";
  ASSERT_GT(model.glb.size(), 12u);
  EXPECT_EQ(std::string(model.glb.begin(), model.glb.begin() + 4), "glTF");
}

TEST(UploadImportTest, AModelThatReachesOutsideItsUploadIsRefused) {
  INKWIRE_REQUIRE_FILE(kBox / "BoxTextured.gltf");
  const fs::path folder = box_upload();
  // The secret sits beside the upload: the buffer names it by a path that climbs out.
  fs::copy_file(folder / "BoxTextured0.bin", folder.parent_path() / "secret.bin", fs::copy_options::overwrite_existing);
  replace_in(folder / "BoxTextured.gltf", "\"BoxTextured0.bin\"", "\"../secret.bin\"");
  confine_model_files(folder);
  const std::string reason = test::error_of([&] { import_upload(folder, {}); });
  EXPECT_NE(reason.find("outside its upload"), std::string::npos) << reason;
}

TEST(UploadImportTest, LimitsOnTrianglesAndTexturePixelsAreHeld) {
  INKWIRE_REQUIRE_FILE(kBox / "BoxTextured.gltf");
  confine_model_files(box_upload());
  EXPECT_NE(test::error_of([&] { import_upload(box_upload(), {.max_triangles = 11}); }).find("12 triangles"), std::string::npos);
  EXPECT_NE(test::error_of([&] { import_upload(box_upload(), {.max_triangles = 100, .max_texture_pixels = 1000}); }).find("44521 pixels"),
            std::string::npos);
}

TEST(UploadImportTest, ATextureClaimingAHugeSizeIsRefusedFromItsHeader) {
  INKWIRE_REQUIRE_FILE(kBox / "BoxTextured.gltf");
  const fs::path folder = box_upload();
  // A PNG whose header says 60000 x 60000 (3.6 gigapixels): decoding it would need 14 GB.
  std::ifstream in(folder / "CesiumLogoFlat.png", std::ios::binary);
  std::string png((std::istreambuf_iterator<char>(in)), {});
  in.close();
  for (int k = 0; k < 2; ++k) {
    const uint32_t side = 60000;
    for (int b = 0; b < 4; ++b) png[size_t(16 + 4 * k + b)] = char(side >> (24 - 8 * b));
  }
  // ... with the header chunk's checksum made right again, as a crafted file would have it.
  const uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(png.data() + 12), 17));
  for (int b = 0; b < 4; ++b) png[size_t(29 + b)] = char(crc >> (24 - 8 * b));
  std::ofstream(folder / "CesiumLogoFlat.png", std::ios::binary) << png;
  confine_model_files(folder);
  const std::string reason = test::error_of([&] { import_upload(folder, {}); });
  EXPECT_NE(reason.find("3600000000 pixels"), std::string::npos) << reason;
}
