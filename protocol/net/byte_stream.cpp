#include "protocol/net/byte_stream.hpp"

#include <filesystem>

#include "common/error.hpp"

namespace inkwire {
namespace {

void must_read(const std::string& path, const char* what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error(std::string("TLS ") + what + " '" + path + "' is not a readable file");
}

}  // namespace

const char* const kTls12Suites =
    "ECDHE-ECDSA-AES128-GCM-SHA256:ECDHE-RSA-AES128-GCM-SHA256:ECDHE-ECDSA-AES256-GCM-SHA384:ECDHE-RSA-AES256-GCM-SHA384:"
    "ECDHE-ECDSA-CHACHA20-POLY1305:ECDHE-RSA-CHACHA20-POLY1305";

std::shared_ptr<asio::ssl::context> server_tls_context(const std::string& certificate, const std::string& key) {
  must_read(certificate, "certificate");
  must_read(key, "key");
  auto context = std::make_shared<asio::ssl::context>(asio::ssl::context::tls_server);
  context->set_options(asio::ssl::context::default_workarounds | asio::ssl::context::no_sslv2 | asio::ssl::context::no_sslv3 |
                       asio::ssl::context::no_tlsv1 | asio::ssl::context::no_tlsv1_1 | asio::ssl::context::single_dh_use);
  // TLS 1.2 as Mozilla's "intermediate" profile has it, ECDHE only: AEAD suites, forward secret
  // (the CBC suites scanners fault, LUCKY13, are not offered); TLS 1.3 as OpenSSL offers it.
  if (SSL_CTX_set_cipher_list(context->native_handle(), kTls12Suites) != 1) throw Error("TLS: OpenSSL takes none of the TLS 1.2 suites");
  std::error_code ec;
  context->use_certificate_chain_file(certificate, ec);
  if (ec) throw Error("TLS certificate '" + certificate + "': " + ec.message());
  context->use_private_key_file(key, asio::ssl::context::pem, ec);
  if (ec) throw Error("TLS key '" + key + "': " + ec.message());
  if (SSL_CTX_check_private_key(context->native_handle()) != 1) throw Error("TLS key '" + key + "' does not belong to certificate '" + certificate + "'");
  return context;
}

std::shared_ptr<asio::ssl::context> client_tls_context(const std::string& ca_file) {
  auto context = std::make_shared<asio::ssl::context>(asio::ssl::context::tls_client);
  context->set_options(asio::ssl::context::default_workarounds | asio::ssl::context::no_sslv2 | asio::ssl::context::no_sslv3 |
                       asio::ssl::context::no_tlsv1 | asio::ssl::context::no_tlsv1_1);
  context->set_verify_mode(asio::ssl::verify_peer);
  std::error_code ec;
  if (ca_file.empty()) {
    context->set_default_verify_paths(ec);
  } else {
    must_read(ca_file, "CA file");
    context->load_verify_file(ca_file, ec);
  }
  if (ec) throw Error("TLS trust '" + (ca_file.empty() ? std::string("system CAs") : ca_file) + "': " + ec.message());
  return context;
}

}  // namespace inkwire
