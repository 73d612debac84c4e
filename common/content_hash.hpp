#pragma once
// Content hashes name assets everywhere (server store, wire, client cache): SHA-256 of the bytes.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

namespace inkwire {

using ContentHash = std::array<uint8_t, 32>;

ContentHash content_hash(const void* data, size_t size);
// Hashes a file in pieces; throws inkwire::Error if it cannot be read.
ContentHash content_hash_of_file(const std::filesystem::path& path);

std::string to_hex(const ContentHash& hash);

}  // namespace inkwire
