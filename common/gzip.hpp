#pragma once
// Bytes gzipped (zlib, RFC 1952) for a reply whose client says `Accept-Encoding: gzip`: what a
// static host does for text (a product's manifest is a third of itself gzipped).
#include <string>
#include <string_view>

namespace inkwire {

std::string gzipped(std::string_view bytes);

}  // namespace inkwire
