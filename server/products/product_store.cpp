#include "server/products/product_store.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>



#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/image_metrics.hpp"
#include "common/log.hpp"
#include "server/products/mesh_product_process.hpp"
#include "server/products/product_samples.hpp"

namespace inkwire::server {
namespace fs = std::filesystem;
using protocol::AssetKind;
using protocol::Bytes;

namespace {

std::string hash_of_file(const fs::path& file) { return to_hex(content_hash_of_file(file)); }

}  // namespace

std::string ProductSource::key() const {
  std::string text;
  if (!mesh.empty()) {
    text = "mesh " + hash_of_file(mesh) + " samples=" + std::to_string(mesh_options.samples) + " size=" +
           std::to_string(mesh_options.size) + " points=" + std::to_string(mesh_options.points) + " style=" + mesh_options.style +
           " sphere=" + std::to_string(mesh_options.sphere_level);
    if (mesh_options.up != UpAxis::Auto) {  // keys made before "up" existed stay valid
      text += " up=";
      text += to_string(mesh_options.up);
    }
  } else {
    const PhotoLayout& layout = photo_options.layout;
    text = "photos step=" + std::to_string(layout.step_degrees) + " arc=" + std::to_string(layout.arc_degrees) +
           " max_side=" + std::to_string(layout.max_side) + " matte=" + photo_options.matte +
           " points=" + std::to_string(photo_options.control_points) + " share=" + std::to_string(photo_options.max_tween_share);
    if (layout.rows != 0) text += " rows=" + std::to_string(layout.rows);
    for (float e : layout.elevations) text += " elevation=" + std::to_string(e);
    std::error_code ec;
    if (!fs::is_directory(photos, ec)) throw Error(photos.string() + " is not a folder");
    // Row folders' photos by their path in the folder (row1/a.jpg); a flat folder's by name.
    std::vector<fs::path> files;
    for (auto it = fs::recursive_directory_iterator(photos, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name[0] == '.') {
        if (it->is_directory()) it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file()) files.push_back(fs::relative(it->path(), photos));
    }
    if (ec) throw Error("cannot list " + photos.string() + ": " + ec.message());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) text += " " + f.generic_string() + "=" + hash_of_file(photos / f);
  }
  text += " format=6";  // bump when the way products are made changes (5: zoom levels; 6: the tween data's share kept, calibrated photos by azimuth)
  const ContentHash h = content_hash(text.data(), text.size());
  return to_hex(h);
}

std::string ProductSource::describe() const { return mesh.empty() ? "photos in " + photos.string() : "mesh " + mesh.string(); }

protocol::Snapshot store_product(AssetStore& store, const Product& product, const std::string& session) {
  if (product.images.size() > protocol::kMaxProductSamples)
    throw Error("a product holds at most " + std::to_string(protocol::kMaxProductSamples) + " samples");
  protocol::Snapshot state;
  state.session = session;
  state.kind = protocol::SessionKind::Turntable;
  state.style = {.renderer = "tween", .settings = {}};
  std::vector<protocol::AssetAnnounce> mattes;
  char name[64];  // "sample-NNN-WIDTH.jpg" with room for any index and width
  for (size_t i = 0; i < product.images.size(); ++i) {
    const Image& image = product.images[i];
    std::snprintf(name, sizeof name, "sample-%03zu.jpg", i);
    // On white: clients bleed the object's colour past the outline themselves (matte_sample()).
    state.assets.push_back(store.add_bytes(stored_photo(image, product.matted), AssetKind::Samples, name));
    if (product.matted) {
      std::snprintf(name, sizeof name, "matte-%03zu.png", i);
      mattes.push_back(store.add_bytes(stored_matte(image), AssetKind::Matte, name));
    }
  }
  state.assets.insert(state.assets.end(), mattes.begin(), mattes.end());
  // Zoom levels (SPEC T18), level after level, each in sample order: every photo read again at
  // its finest, then scaled down level by level.
  std::vector<std::vector<protocol::AssetAnnounce>> levels(product.levels.size());
  for (size_t i = 0; i < product.images.size() && !levels.empty(); ++i) {
    const Image finest = product.finer(i, product.images[i], product.levels.back());
    for (size_t l = 0; l < levels.size(); ++l) {
      const glm::ivec2 size = product.levels[l];
      const Image level = l + 1 == levels.size() ? finest : resized(finest, size.x, size.y);
      std::snprintf(name, sizeof name, "sample-%03zu-%d.jpg", i, size.x);
      levels[l].push_back(store.add_bytes(stored_photo(level, product.matted), AssetKind::Zoom, name));
    }
  }
  for (const auto& level : levels) state.assets.insert(state.assets.end(), level.begin(), level.end());
  const std::vector<uint8_t> tween = encode_tween(product.data);
  state.assets.push_back(store.add_bytes(Bytes(tween.begin(), tween.end()), AssetKind::Tween, "tween.iktw"));
  state.product = {.width = uint16_t(product.data.width), .height = uint16_t(product.data.height),
                   .directions = quantised(product.data).directions, .cells = uint16_t(product.data.cells.size()),
                   .distance_diagonals = product.distance_diagonals, .fov_y_degrees = product.fov_y_degrees, .levels = {}};
  for (const glm::ivec2& l : product.levels) state.product.levels.push_back({uint16_t(l.x), uint16_t(l.y)});
  return state;
}

protocol::Snapshot find_or_make_product(AssetStore& store, const ProductSource& source, const std::string& session,
                                        const PairProgress& progress, bool* made, const MeshRenderer& render_mesh) {
  const std::string key = source.key();
  // The same product under another name is the same assets under another session.
  const auto found = [&]() -> std::optional<protocol::Snapshot> {
    auto stored = store.find_product(key);
    if (!stored) return std::nullopt;
    for (const auto& a : stored->assets)
      if (!store.find(a.hash)) return std::nullopt;
    stored->session = session;
    return stored;
  };
  if (auto stored = found()) {
    if (made) *made = false;
    return *stored;
  }
  if (!source.mesh.empty() && !render_mesh) {
    make_mesh_product_in_helper(store.dir(), source, progress);
    auto stored = found();
    if (!stored) throw Error("the mesh helper stored no product for " + source.mesh.string());
    if (made) *made = true;
    return *stored;
  }
  const auto start = std::chrono::steady_clock::now();
  const Product product = source.mesh.empty() ? product_from_photos(source.photos, source.photo_options, progress)
                                              : render_mesh(source.mesh, source.mesh_options, progress);
  protocol::Snapshot state = store_product(store, product, session);
  store.save_product(key, state);
  if (made) *made = true;
  log_info("product-made", {{"session", session}, {"source", source.describe()}, {"samples", product.images.size()},
                            {"matted", product.matted},
                            {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}});
  return state;
}

std::vector<uint64_t> zoom_level_bytes(const protocol::Snapshot& state) {
  std::vector<uint64_t> levels(state.product.levels.size(), 0);
  size_t zoomed = 0;
  for (const auto& a : state.assets)
    if (a.kind == AssetKind::Zoom) levels.at(zoomed++ / state.product.directions.size()) += a.size;
  return levels;
}

std::vector<protocol::TweenData> product_tween_messages(const AssetStore& store, const protocol::Snapshot& state) {
  const protocol::Product& p = state.product;
  if (p.directions.empty()) throw Error("session '" + state.session + "' has no product");
  std::optional<TweenData> data;
  size_t samples = 0, mattes = 0, zoom = 0;
  for (const auto& asset : state.assets) {
    const Bytes bytes = store.read_verified(asset.hash);  // every file checked, not only the tween data
    if (asset.kind == AssetKind::Samples) ++samples;
    if (asset.kind == AssetKind::Matte) ++mattes;
    if (asset.kind == AssetKind::Zoom) ++zoom;
    if (asset.kind == AssetKind::Tween) data = decode_tween(bytes);
  }
  if (!data) throw Error("product of '" + state.session + "' has no tween data");
  if (samples != p.directions.size() || (mattes != 0 && mattes != samples) || zoom != samples * p.levels.size())
    throw Error("product of '" + state.session + "' lists " + std::to_string(samples) + " photos, " + std::to_string(mattes) +
                " mattes and " + std::to_string(zoom) + " zoom photos for " + std::to_string(p.directions.size()) + " samples and " +
                std::to_string(p.levels.size()) + " zoom levels");
  if (data->width != p.width || data->height != p.height || data->sample_count() != int(p.directions.size()) ||
      data->cells.size() != p.cells)
    throw Error("product of '" + state.session + "': its tween data does not match its photos");
  std::vector<protocol::TweenData> messages;
  for (size_t i = 0; i < data->cells.size(); ++i) {
    const std::vector<uint8_t> cell = encode_tween_cell(data->cells[i], data->width, data->height, data->sample_count());
    messages.push_back({.pair = uint16_t(i), .data = Bytes(cell.begin(), cell.end())});
  }
  return messages;
}

}  // namespace inkwire::server
