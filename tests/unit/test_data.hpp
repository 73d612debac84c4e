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

// Writes `text` to a fresh file in the test output folder and returns its path.
inline std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(INKWIRE_TEST_OUTPUT_DIR) / "tmp";
  std::filesystem::create_directories(dir);
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
