#pragma once
// Session tokens as the server keeps them (SPEC D3): never the token itself, only its SHA-256,
// and a guess is compared with it in constant time, so neither the catalogue, the broker nor the
// time an answer takes gives the token away.
#include <string>

namespace inkwire::server {

// "sha256:" and the hex digest of `token`; empty for an empty token (anyone may join).
std::string hash_token(const std::string& token);
// A stored token that is not a digest yet (a catalogue of an older version) as one.
std::string as_token_hash(const std::string& stored);
// Whether `guess` is the token whose hash is `stored` (always, when nothing is stored).
bool token_matches(const std::string& stored, const std::string& guess);
// Whether two secrets are equal, compared in constant time.
bool same_secret(const std::string& a, const std::string& b);
// `bytes` random bytes from OpenSSL, as lowercase hex (a one-time ticket).
std::string random_hex(size_t bytes);

}  // namespace inkwire::server
