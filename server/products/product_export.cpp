#include "server/products/product_export.hpp"

#include <fstream>

#include "common/error.hpp"
#include "server/products/product_listing.hpp"
#include "server/products/product_store.hpp"
#include "server/web/web_files.hpp"

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;

// Writes `bytes` to `path` through a .partial and a rename; a file already holding exactly
// these bytes is kept. True when it was written.
bool write_file(const fs::path& path, std::string_view bytes, ExportSummary& summary) {
  std::error_code ec;
  if (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == bytes.size()) {
    std::ifstream in(path, std::ios::binary);
    std::string old(bytes.size(), '\0');
    if (in.read(old.data(), std::streamsize(old.size())) && old == bytes) {
      ++summary.kept;
      return false;
    }
  }
  fs::create_directories(path.parent_path(), ec);
  const fs::path partial = path.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw Error("cannot write '" + partial.string() + "'");
  }
  fs::rename(partial, path, ec);
  if (ec) throw Error("cannot write '" + path.string() + "': " + ec.message());
  ++summary.written;
  summary.bytes_written += bytes.size();
  return true;
}

std::string_view as_text(const protocol::Bytes& b) { return {reinterpret_cast<const char*>(b.data()), b.size()}; }

}  // namespace

ExportSummary export_product(const AssetStore& store, const protocol::Snapshot& state, const fs::path& dir) {
  // The tween cells as a member receives them; every stored file is checked on the way.
  const ProductListing listing = product_listing(state, product_tween_messages(store, state));
  ExportSummary summary;
  for (const auto& [name, file] : listing.files)
    write_file(dir / name, as_text(file.cell ? *file.cell : store.read_verified(file.hash)), summary);
  // The element itself: its scripts and shaders at the paths they import each other by.
  for (const auto* files : {&web_client_files(), &web_shader_files()})
    for (const auto& [path, bytes] : *files) write_file(dir / path, bytes, summary);
  // The manifest last: until it is renamed into place, visitors read the previous one. Beside it
  // the same gzipped, which a static host sends as it is to browsers that take gzip (nginx's
  // gzip_static, deploy/nginx/): compressing it per visit was most of nginx's time per visitor.
  write_file(dir / "product.json.gz", listing.manifest_gzipped, summary);
  write_file(dir / "product.json", listing.manifest, summary);
  summary.first_view_bytes = listing.first_view_bytes;
  return summary;
}

}  // namespace inkwire::server
