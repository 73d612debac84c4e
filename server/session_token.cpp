#include "server/session_token.hpp"

#include <vector>

#include <openssl/crypto.h>
#include <openssl/rand.h>

#include "common/error.hpp"

#include "common/content_hash.hpp"

namespace inkwire::server {
namespace {

constexpr std::string_view kPrefix = "sha256:";

}  // namespace

std::string hash_token(const std::string& token) {
  return token.empty() ? std::string() : std::string(kPrefix) + to_hex(content_hash(token.data(), token.size()));
}

std::string as_token_hash(const std::string& stored) { return stored.empty() || stored.starts_with(kPrefix) ? stored : hash_token(stored); }

bool token_matches(const std::string& stored, const std::string& guess) {
  if (stored.empty()) return true;
  // Both digests have the same length whatever was guessed, so the comparison's time says nothing.
  const std::string hashed = hash_token(guess);
  return hashed.size() == stored.size() && CRYPTO_memcmp(hashed.data(), stored.data(), stored.size()) == 0;
}

bool same_secret(const std::string& a, const std::string& b) {
  return a.size() == b.size() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

std::string random_hex(size_t bytes) {
  std::vector<uint8_t> random(bytes);
  if (RAND_bytes(random.data(), int(bytes)) != 1) throw Error("no randomness from OpenSSL");
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  for (const uint8_t b : random) out += kDigits[b >> 4], out += kDigits[b & 15];
  return out;
}

}  // namespace inkwire::server
