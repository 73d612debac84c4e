#pragma once
// Products kept in the server's store (SPEC T11): each sample photo as a JPEG and its matte as a
// PNG, the tween data as one IKTW asset, all content-addressed, and a catalogue row that maps
// the product's key (a hash of its inputs and settings) to them, so a product is made once and
// never again on restart or when added a second time.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "protocol/messages.hpp"
#include "server/asset_store.hpp"
#include "server/products/product.hpp"

namespace inkwire::server {

// Where a product comes from: a folder of photos or a mesh, with the settings it is made with.
struct ProductSource {
  std::filesystem::path photos, mesh;  // exactly one is set
  PhotoProductOptions photo_options;
  MeshProductOptions mesh_options;

  // A hash of every input byte (each photo and calibration, or the mesh file) and every setting.
  // Throws inkwire::Error if an input cannot be read.
  std::string key() const;
  std::string describe() const;
};

// Stores `product`'s photos, mattes and tween data as assets and returns the state of a
// turntable session named `session` that shows it.
protocol::Snapshot store_product(AssetStore& store, const Product& product, const std::string& session);

// How a mesh becomes a product in this process: tools/mesh_product.hpp's product_from_mesh,
// in the helper that links GL. Without one, a mesh product is made by that helper as a process
// of its own (mesh_product_process.hpp), so the caller never loads GL.
using MeshRenderer = std::function<Product(const std::filesystem::path&, const MeshProductOptions&, const PairProgress&)>;

// The product of `source` for a turntable session named `session`: found by its key in the
// catalogue, or made (landmarks and all, with `progress` per pair) and stored. `made` says
// which. Throws inkwire::Error with a one-line reason.
protocol::Snapshot find_or_make_product(AssetStore& store, const ProductSource& source, const std::string& session,
                                        const PairProgress& progress, bool* made = nullptr, const MeshRenderer& render_mesh = {});

// The bytes of each of a product's zoom levels (all its photos at that level), coarsest first.
std::vector<uint64_t> zoom_level_bytes(const protocol::Snapshot& state);

// A stored product's tween data as the messages a member receives after the snapshot, one per
// cell. Every asset of the product is read back and checked against its hash first, so a
// corrupted file is found here, not served. Throws inkwire::Error naming what is wrong.
std::vector<protocol::TweenData> product_tween_messages(const AssetStore& store, const protocol::Snapshot& state);

}  // namespace inkwire::server
