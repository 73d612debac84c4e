#pragma once
// Mesh products made in a process of their own (issue: a server without GL): the serving
// process (and `inkwire-server add-product --mesh`) runs inkwire-mesh-product, the helper that
// links the renderer, beside its own program file. The helper makes the product into the same
// data folder (the catalogue is SQLite in WAL mode: two processes may write it) and says each
// pair done on its standard output; the caller then finds the product by its key as any stored
// product. A helper that crashes or fails costs that one product, with its reason.
#include <filesystem>
#include <string>
#include <vector>

#include "server/products/product.hpp"

namespace inkwire::server {

struct ProductSource;

// The helper's file: inkwire-mesh-product beside the running program.
std::filesystem::path mesh_product_helper();

// Runs the helper for `source` (a mesh) into the store at `data`, passing its pairs and notes
// to `progress`. Throws inkwire::Error with the helper's own reason when it fails.
void make_mesh_product_in_helper(const std::filesystem::path& data, const ProductSource& source, const PairProgress& progress);

// The helper's arguments for `source` (its options: tools/inkwire_mesh_product.cpp).
std::vector<std::string> mesh_product_arguments(const std::filesystem::path& data, const ProductSource& source);

}  // namespace inkwire::server
