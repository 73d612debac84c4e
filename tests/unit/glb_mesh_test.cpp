// The browser module's GLB reader (common/glb_mesh) makes of a model what the native reader
// (assimp, common/mesh_import) makes of it, so both clients draw the same mesh; and it refuses
// broken GLBs with one line. Reads libcgal-demo's cow and assimp-testmodels' GLBs (skips
// without them).
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "common/glb_mesh.hpp"
#include "common/mesh_import.hpp"
#include "common/model_bundle.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

namespace {

std::vector<uint8_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_same_mesh(const Mesh& native, const Mesh& module) {
  ASSERT_EQ(native.positions.size(), module.positions.size());
  ASSERT_EQ(native.triangles.size(), module.triangles.size());
  EXPECT_EQ(native.positions, module.positions);
  EXPECT_EQ(native.triangles, module.triangles);
  ASSERT_EQ(native.colours.size(), module.colours.size());
  for (size_t i = 0; i < native.colours.size(); ++i) EXPECT_LT(glm::length(native.colours[i] - module.colours[i]), 1e-5f) << i;
  ASSERT_EQ(native.corner_uvs.size(), module.corner_uvs.size());
  for (size_t t = 0; t < native.corner_uvs.size(); ++t)
    for (int c = 0; c < 3; ++c) EXPECT_LT(glm::length(native.corner_uvs[t][size_t(c)] - module.corner_uvs[t][size_t(c)]), 1e-6f) << t;
  // Each triangle's material alike (assimp numbers a glTF's materials in the order meshes first
  // use them, this reader in the file's order: the numbers may differ, never what they draw).
  ASSERT_EQ(native.materials.size(), module.materials.size());
  for (size_t t = 0; t < native.triangles.size(); ++t) {
    const Material &a = native.materials[native.material_of(t)], &b = module.materials[module.material_of(t)];
    EXPECT_LT(glm::length(a.base_colour - b.base_colour), 1e-5f) << t;
    EXPECT_EQ(a.texture_bytes, b.texture_bytes) << t;
  }
}

}  // namespace

TEST(GlbMeshTest, AnOffMadeIntoAGlbReadsAsAssimpReadsItAndKeepsItsShape) {
  const auto cow = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(cow);
  const std::optional<SelfContainedModel> glb = self_contained_model(cow);
  ASSERT_TRUE(glb) << "an OFF travels as a GLB";
  const auto file = scratch_dir() / glb->name;
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(glb->bytes.data()), std::streamsize(glb->bytes.size()));
  const Mesh native = load_mesh(file);
  expect_same_mesh(native, read_glb_mesh(glb->bytes, glb->name));
  // The GLB holds the OFF's own mesh: as many welded positions and triangles, indexed (not one
  // vertex a corner) so it is hardly larger than the text file.
  const Mesh off = load_mesh(cow);
  EXPECT_EQ(off.positions.size(), native.positions.size());
  EXPECT_EQ(off.triangles.size(), native.triangles.size());
  EXPECT_LT(glb->bytes.size(), 2 * std::filesystem::file_size(cow));
}

TEST(GlbMeshTest, TexturedAndMultiPartGlbsReadAsAssimpReadsThem) {
  size_t read = 0;
  for (const char* path : {"/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                           "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"}) {
    if (!std::filesystem::exists(path)) continue;
    SCOPED_TRACE(path);
    expect_same_mesh(load_mesh(path), read_glb_mesh(read_bytes(path), "model.glb"));
    ++read;
  }
  if (read == 0) GTEST_SKIP() << "needs Debian's assimp-testmodels (install with scripts/setup.sh)";
}

TEST(GlbMeshTest, BrokenGlbsAreRefusedWithOneLine) {
  const auto cow = cgal_mesh("cow.off");
  INKWIRE_REQUIRE_FILE(cow);
  const std::vector<uint8_t> glb = self_contained_model(cow)->bytes;
  const auto refused = [](std::vector<uint8_t> bytes) { return error_of([&] { read_glb_mesh(bytes, "m.glb"); }); };
  EXPECT_NE(refused({}).find("m.glb: the model is empty"), std::string::npos);
  EXPECT_NE(refused({'n', 'o', 't', ' ', 'g', 'l', 'b'}).find("m.glb: not a GLB model"), std::string::npos);
  std::vector<uint8_t> truncated(glb.begin(), glb.begin() + std::ptrdiff_t(glb.size() / 2));
  EXPECT_NE(refused(truncated), "");
  for (size_t cut = 12; cut < glb.size(); cut += glb.size() / 7) {
    std::vector<uint8_t> damaged = glb;
    for (size_t i = cut; i < std::min(damaged.size(), cut + 64); ++i) damaged[i] ^= 0xA5;
    const std::string reason = refused(damaged);  // refused or read: never a crash
    EXPECT_EQ(reason.find('\n'), std::string::npos) << reason;
  }
}
