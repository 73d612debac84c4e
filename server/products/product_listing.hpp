#pragma once
// A product's manifest and the files it names (protocol/PRODUCT.md), worked out once from the
// session's state and its tween cells: what an export writes into a folder and what the
// server's HTTP listener serves at /products/NAME/ (SPEC T20-T21), so both say the same thing.
#include <cstdint>
#include <map>
#include <string>

#include "protocol/messages.hpp"

namespace inkwire::server {

inline constexpr int kProductManifestVersion = 1;

// One file of the product by the name the manifest gives it ("files/HEX.jpg"): a stored asset
// (read from the asset store by `hash`), or a tween cell, whose bytes are here (cells are not
// stored one by one).
struct ProductFile {
  protocol::Hash hash{};
  uint64_t size = 0;
  std::string content_type;
  std::optional<protocol::Bytes> cell;
};

struct ProductListing {
  std::string manifest;                        // product.json's text
  std::string manifest_gzipped;                // the same gzipped once (product.json.gz, the HTTP reply)
  std::string etag;                            // the manifest's quoted entity tag, from its hash
  std::map<std::string, ProductFile> files;    // by their name in the manifest
  uint64_t first_view_bytes = 0;               // the manifest, one photo and its matte
};

// Throws inkwire::Error when `state` is no product.
ProductListing product_listing(const protocol::Snapshot& state, const std::vector<protocol::TweenData>& cells);

}  // namespace inkwire::server
