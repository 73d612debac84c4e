// Import of real packaged models, and refusal of the deliberately broken ones (SPEC G1, X2).
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/mesh_import.hpp"
#include "test_data.hpp"

using namespace inkwire;
using namespace inkwire::test;

namespace {

// Every file in assimp-testmodels' invalid/ folder and its deliberately broken glTF2 folders.
std::vector<std::filesystem::path> broken_corpus() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path root = kAssimpModels;
  for (const char* dir : {"invalid", "glTF2/IndexOutOfRange", "glTF2/MissingBin", "glTF2/SchemaFailures",
                          "glTF2/wrongTypes", "glTF2/BoxWithInfinites-glTF-Binary", "glTF2/RecursiveNodes",
                          "glTF2/TestNoRootNode", "glTF2/IncorrectVertexArrays"}) {
    if (!std::filesystem::is_directory(root / dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(root / dir)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".txt" || ext == ".png" || ext == ".bin") continue;  // documentation and side files
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST(MeshImportTest, BrokenCorpusEndsInOneLineErrors) {
  const auto files = broken_corpus();
  if (files.empty()) GTEST_SKIP() << "needs Debian's assimp-testmodels (install with scripts/setup.sh)";
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    try {
      const Mesh mesh = load_mesh(file);
      ADD_FAILURE() << "loaded " << mesh.face_count() << " triangles from a broken file";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_FALSE(what.empty());
      EXPECT_EQ(what.find('\n'), std::string::npos);
      EXPECT_NE(what.find(file.filename().string()), std::string::npos) << "error should name the file: " << what;
    }
  }
}

TEST(MeshImportTest, MissingAndEmptyFilesAreRefused) {
  EXPECT_THROW(load_mesh("/nonexistent/mesh.obj"), Error);
  EXPECT_THROW(load_mesh(write_temp("empty.obj", "")), Error);
  EXPECT_THROW(load_mesh(write_temp("garbage.obj", std::string(4096, '\x7f'))), Error);
}

TEST(MeshImportTest, ObjWithSplitCornersIsWelded) {
  // A quad as two triangles whose shared corners are written twice (as exporters do when
  // normals or UVs differ): welding must join them so the diagonal is one shared edge.
  const auto file = write_temp("quad.obj",
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                               "f 1/1 2/2 3/3\nf 4/1 5/3 6/4\n");
  const Mesh mesh = load_mesh(file);
  EXPECT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.face_count(), 2u);
  ASSERT_TRUE(mesh.has_uvs());
  EXPECT_FLOAT_EQ(mesh.corner_uvs[1][2].y, 1.0f);
}

TEST(MeshImportTest, PolygonsAreTriangulated) {
  const auto file = write_temp("pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n");
  EXPECT_EQ(load_mesh(file).face_count(), 3u);
}

TEST(MeshImportTest, PackagedFormatsLoad) {
  // One real model per format the spec names (G1), all from Debian packages.
  const std::vector<std::filesystem::path> files = {
      cgal_mesh("cow.off"),
      kAssimpModels / "OBJ/WusonOBJ.obj",
      kAssimpModels / "PLY/cube.ply",
      kAssimpModels / "3DS/fels.3ds",
      kAssimpModels / "ASE/ThreeCubesGreen.ASE",
      kAssimpModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf",
  };
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    if (!std::filesystem::exists(f)) {
      ADD_FAILURE() << "missing packaged model (install with scripts/setup.sh)";
      continue;
    }
    const Mesh mesh = load_mesh(f);
    EXPECT_GT(mesh.face_count(), 0u);
  }
}

TEST(MeshImportTest, GltfTextureAndUvsAreKept) {
  const auto file = kAssimpModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf";
  INKWIRE_REQUIRE_FILE(file);
  const Mesh mesh = load_mesh(file);
  EXPECT_TRUE(mesh.has_uvs());
  bool textured = false;
  for (const Material& m : mesh.materials) textured = textured || m.textured();
  EXPECT_TRUE(textured);
}

TEST(MeshImportTest, TexturesNamedTheWindowsWayAreFound) {
  // jeep1.ms3d names its texture ".\jeep1.jpg", which on this system is one odd file name.
  const auto jeep = kAssimpModels / "MS3D/jeep1.ms3d";
  INKWIRE_REQUIRE_FILE(jeep);
  INKWIRE_REQUIRE_FILE(kAssimpModels / "MS3D/jeep1.jpg");
  const Mesh mesh = load_mesh(jeep);
  EXPECT_TRUE(mesh.has_uvs());
  EXPECT_EQ(mesh.materials.at(0).texture_file, kAssimpModels / "MS3D/jeep1.jpg");
  // earthCylindrical.DAE names "\..\LWO\LWO2\MappingModes\EarthCylindric.jpg": from a root
  // meaning its own folder, and with a capital E the file does not have.
  const auto earth = kAssimpModels / "Collada/earthCylindrical.DAE";
  INKWIRE_REQUIRE_FILE(earth);
  bool textured = false;
  for (const Material& m : load_mesh(earth).materials)
    textured = textured || m.texture_file == kAssimpModels / "LWO/LWO2/MappingModes/earthCylindric.jpg";
  EXPECT_TRUE(textured);
}
