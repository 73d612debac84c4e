#include "common/model_files.hpp"

#include <optional>

namespace inkwire {
namespace {

namespace fs = std::filesystem;

std::optional<fs::path> confined_to;  // canonical, set once by the importing process
std::string first_refused;

}  // namespace

void confine_model_files(const fs::path& folder) {
  confined_to = fs::weakly_canonical(folder);
  first_refused.clear();
}

bool model_file_allowed(const fs::path& file) {
  if (!confined_to) return true;
  std::error_code ec;
  // Links resolved: a symbolic link in the folder pointing out of it is outside.
  const fs::path real = fs::weakly_canonical(fs::absolute(file, ec), ec);
  if (ec) return false;
  const auto [folder_end, unused] = std::mismatch(confined_to->begin(), confined_to->end(), real.begin(), real.end());
  const bool inside = folder_end == confined_to->end() && real != *confined_to;
  if (!inside && first_refused.empty()) first_refused = file.filename().string();
  return inside;
}

std::string refused_model_file() { return first_refused; }

bool ModelIOSystem::Exists(const char* file) const { return model_file_allowed(file) && DefaultIOSystem::Exists(file); }

Assimp::IOStream* ModelIOSystem::Open(const char* file, const char* mode) {
  if (!model_file_allowed(file)) return nullptr;
  return DefaultIOSystem::Open(file, mode);
}

}  // namespace inkwire
