#include "common/content_hash.hpp"

#include <fstream>
#include <memory>
#include <vector>

#include <openssl/evp.h>

#include "common/error.hpp"

namespace inkwire {
namespace {

struct Digest {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx{EVP_MD_CTX_new(), &EVP_MD_CTX_free};
  Digest() {
    if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) throw Error("SHA-256 is unavailable");
  }
  void add(const void* data, size_t size) { EVP_DigestUpdate(ctx.get(), data, size); }
  ContentHash finish() {
    ContentHash hash{};
    unsigned int n = 0;
    EVP_DigestFinal_ex(ctx.get(), hash.data(), &n);
    return hash;
  }
};

}  // namespace

ContentHash content_hash(const void* data, size_t size) {
  Digest d;
  d.add(data, size);
  return d.finish();
}

ContentHash content_hash_of_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read '" + path.string() + "'");
  Digest d;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    d.add(buffer.data(), size_t(in.gcount()));
  }
  if (in.bad()) throw Error("error reading '" + path.string() + "'");
  return d.finish();
}

std::string to_hex(const ContentHash& hash) {
  static const char* digits = "0123456789abcdef";
  std::string hex;
  for (uint8_t b : hash) hex += digits[b >> 4], hex += digits[b & 15];
  return hex;
}

}  // namespace inkwire
