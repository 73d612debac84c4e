#include "server/session_token.hpp"

#include <openssl/crypto.h>

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

}  // namespace inkwire::server
