#pragma once
// Where tests find real data. Packaged meshes come from Debian (libcgal-demo, extracted at
// configure time; assimp-testmodels; glmark2-data); tests that need one skip with a message
// when it is absent rather than pass silently.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"

namespace inkwire::test {

inline std::filesystem::path cgal_mesh(const std::string& name) { return std::filesystem::path(INKWIRE_MESH_DIR) / name; }
inline const std::filesystem::path kAssimpModels = "/usr/share/assimp/models";

// A folder of the running test's own in the test output folder: ctest runs each test as its
// own process, several at once, so files two tests name alike must not meet.
inline std::filesystem::path scratch_dir() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = test ? std::string(test->test_suite_name()) + "." + test->name() : "outside-a-test";
  for (char& c : name)
    if (c == '/') c = '_';  // parameterised tests are named Prefix/Suite.Test/param
  const std::filesystem::path dir = std::filesystem::path(INKWIRE_TEST_OUTPUT_DIR) / "tmp" / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes `text` to a fresh file in the running test's scratch folder and returns its path.
inline std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = scratch_dir();
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

// The one-line reason `action` was refused with (its inkwire::Error), or "" when it was not.
template <class Action>
std::string error_of(Action action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace inkwire::test

#define INKWIRE_REQUIRE_FILE(path)                                                           \
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs " << (path) << " (install with scripts/setup.sh)"
