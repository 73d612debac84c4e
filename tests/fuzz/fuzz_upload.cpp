// libFuzzer target: an upload's body as the serving process reads it (server/making/
// multipart.hpp): a multipart/form-data body split into pieces of the sizes its first byte
// chooses, its files written into a folder, then the model among them picked. The model itself
// is imported by inkwire-import-model, a process of its own under limits; the seeds wrap the
// assimp-testmodels invalid corpus (scripts/fuzz.sh).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "common/error.hpp"
#include "server/making/multipart.hpp"
#include "server/making/upload_import.hpp"

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const fs::path folder = fs::temp_directory_path() / ("fuzz-upload-" + std::to_string(getpid()));
  std::error_code ec;
  fs::remove_all(folder, ec);
  fs::create_directories(folder);
  const size_t piece = 1 + data[0] % 97;
  const std::string_view body(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    inkwire::server::MultipartFiles files("inkwire-fuzz-boundary", folder);
    for (size_t at = 0; at < body.size(); at += piece) files.feed(body.substr(at, piece));
    files.finish();
    for (const std::string& name : files.files())
      if (!inkwire::server::upload_file_name_allowed(name) || !fs::exists(folder / name)) __builtin_trap();  // a name let through that should not be
    (void)inkwire::server::upload_model_file(files.files());
  } catch (const inkwire::Error&) {
  }
  fs::remove_all(folder, ec);
  return 0;
}
