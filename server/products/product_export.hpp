#pragma once
// A product as a folder of static files (SPEC T20, protocol/PRODUCT.md): every photo level, matte
// and tween cell under its content hash (files/HEX.jpg, .png, .cell: immutable names), the
// manifest product.json (the one name whose content changes), and the element's scripts and
// shaders, so the folder alone is a working product on any static host or CDN. A visitor never
// meets half an export: every file goes through a .partial and a rename, the manifest last;
// files already there (an earlier export) are kept, so a second export adds only what changed.
#include <cstdint>
#include <filesystem>

#include "protocol/messages.hpp"
#include "server/asset_store.hpp"

namespace inkwire::server {

struct ExportSummary {
  size_t written = 0, kept = 0;  // files written now, and already there with the same bytes
  uint64_t bytes_written = 0;
  uint64_t first_view_bytes = 0;  // the manifest, one photo and its matte
};

// Writes the product of the turntable session `state` (stored in `store`) into `dir`. Every
// stored file is checked against its hash first. Throws inkwire::Error with a one-line reason.
ExportSummary export_product(const AssetStore& store, const protocol::Snapshot& state, const std::filesystem::path& dir);

}  // namespace inkwire::server
