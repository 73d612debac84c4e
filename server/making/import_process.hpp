#pragma once
// An upload's model imported by inkwire-import-model (server/apps/inkwire_import_model.cpp), a
// process of its own under the operator's memory and time limits, while the server's I/O thread
// serves everyone else: its one line of JSON is read through a pipe on the I/O context, and past
// the time limit (wall clock) it is killed. What it costs, it costs alone.
#include <cstdint>
#include <filesystem>
#include <string>

#include <asio.hpp>

#include "server/making/making_options.hpp"

namespace inkwire::server {

struct ImportOutcome {
  std::string error;  // empty when the GLB was written
  std::string name;   // the model's name, .glb
  uint64_t triangles = 0, texture_pixels = 0, bytes = 0;
};

// The importer beside this program (build/bin/inkwire-import-model).
std::filesystem::path model_importer();

// Imports the model among `folder`'s files into the GLB `out`. Never throws: a failure (the
// importer's reason, a crash, a timeout, a missing importer) is the outcome's error.
asio::awaitable<ImportOutcome> import_model(std::filesystem::path folder, std::filesystem::path out, const MakingOptions& options);

}  // namespace inkwire::server
