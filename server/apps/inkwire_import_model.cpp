// inkwire-import-model: the model someone uploaded (the files in --folder) made into one GLB at
// --out and checked against the server's limits, for inkwire-server, which runs it as a process
// of its own for every upload (server/making/import_process.hpp) so that a hostile file costs
// only this process: it limits its own memory and CPU time before it reads a byte, and reads no
// file outside the folder. Prints one JSON line, {"name", "triangles", "texture_pixels",
// "bytes"} or {"error": reason}, and exits 0 only when the GLB is written.
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/model_files.hpp"
#include "server/making/upload_import.hpp"

using namespace inkwire;

namespace {

void limit(int resource, rlim_t value) {
  const rlimit l{value, value};
  if (setrlimit(resource, &l) != 0) throw Error("cannot limit the importer's resources");
}

int say(const nlohmann::json& line, int status) {
  std::cout << line.dump() << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string folder, out;
  server::ImportLimits limits;
  double seconds = 30;
  uint64_t memory = 2ull << 30;
  CLI::App app{"inkwire-import-model: an uploaded model made into one checked GLB (run by inkwire-server)"};
  app.add_option("--folder", folder, "the upload's files")->required();
  app.add_option("--out", out, "the GLB to write")->required();
  app.add_option("--max-triangles", limits.max_triangles, "triangles the model may have");
  app.add_option("--max-texture-pixels", limits.max_texture_pixels, "pixels its textures may hold together");
  app.add_option("--seconds", seconds, "CPU seconds it may take");
  app.add_option("--memory-bytes", memory, "address space it may use");
  CLI11_PARSE(app, argc, argv);
  try {
    limit(RLIMIT_AS, rlim_t(memory));
    limit(RLIMIT_CPU, rlim_t(std::ceil(seconds)));
    limit(RLIMIT_CORE, 0);
    limit(RLIMIT_FSIZE, rlim_t(1) << 30);
    confine_model_files(folder);
    const server::ImportedModel model = server::import_upload(folder, limits);
    std::ofstream file(out, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(model.glb.data()), std::streamsize(model.glb.size()));
    file.close();
    if (!file) throw Error("cannot write the GLB");
    return say({{"name", model.name}, {"triangles", model.triangles}, {"texture_pixels", model.texture_pixels}, {"bytes", model.glb.size()}}, 0);
  } catch (const std::bad_alloc&) {
    return say({{"error", "the model needs more memory than this server gives an upload (" + std::to_string(memory >> 20) + " MiB)"}}, 1);
  } catch (const std::exception& e) {
    return say({{"error", e.what()}}, 1);
  }
}
