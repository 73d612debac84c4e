#pragma once
// A connection's bytes, plain TCP or TLS over TCP (SPEC D3), behind one Asio stream type, so the
// protocol's framing, the HTTP listener, WebSockets and the client read and write the same way
// whichever it is (asio::async_read / async_write and coroutines work on it as on a socket).
// TLS comes from Asio's OpenSSL support; a TLS stream must finish its handshake first.
#include <memory>
#include <optional>
#include <string>

#include <asio.hpp>
#include <asio/ssl.hpp>

namespace inkwire {

class ByteStream {
 public:
  using executor_type = asio::any_io_executor;
  using Tls = asio::ssl::stream<asio::ip::tcp::socket>;

  explicit ByteStream(asio::ip::tcp::socket socket) : plain_(std::move(socket)) {}
  ByteStream(asio::ip::tcp::socket socket, asio::ssl::context& tls) : tls_(std::make_unique<Tls>(std::move(socket), tls)) {}
  ByteStream(ByteStream&&) = default;
  ByteStream& operator=(ByteStream&&) = default;

  bool tls() const { return tls_ != nullptr; }
  Tls* tls_stream() { return tls_.get(); }  // for the handshake; null for plain TCP
  asio::ip::tcp::socket& socket() { return tls_ ? tls_->next_layer() : *plain_; }
  const asio::ip::tcp::socket& socket() const { return tls_ ? tls_->next_layer() : *plain_; }
  executor_type get_executor() { return socket().get_executor(); }

  template <class MutableBuffers, class Token>
  auto async_read_some(const MutableBuffers& buffers, Token&& token) {
    return asio::async_initiate<Token, void(std::error_code, size_t)>(
        [this](auto handler, const MutableBuffers& b) {
          if (tls_) tls_->async_read_some(b, std::move(handler));
          else plain_->async_read_some(b, std::move(handler));
        },
        token, buffers);
  }
  template <class ConstBuffers, class Token>
  auto async_write_some(const ConstBuffers& buffers, Token&& token) {
    return asio::async_initiate<Token, void(std::error_code, size_t)>(
        [this](auto handler, const ConstBuffers& b) {
          if (tls_) tls_->async_write_some(b, std::move(handler));
          else plain_->async_write_some(b, std::move(handler));
        },
        token, buffers);
  }

  // Shuts the TCP connection down both ways and closes it, ignoring errors (the peer may be
  // gone). No TLS close_notify: it would wait on a peer that may never answer.
  void close() {
    if (!tls_ && !plain_) return;  // moved from
    std::error_code ec;
    socket().shutdown(asio::ip::tcp::socket::shutdown_both, ec);
    socket().close(ec);
  }

 private:
  std::optional<asio::ip::tcp::socket> plain_;
  std::unique_ptr<Tls> tls_;
};

// A server's TLS context from a PEM certificate chain and private key (TLS 1.2 and newer).
// Throws inkwire::Error naming the file that cannot be used.
// The TLS 1.2 suites a server offers (OpenSSL's names): ECDHE with AES-GCM or ChaCha20-Poly1305.
extern const char* const kTls12Suites;
std::shared_ptr<asio::ssl::context> server_tls_context(const std::string& certificate, const std::string& key);
// A client's: trusts the CAs of `ca_file` (PEM), or the system's when empty, and verifies the
// server's certificate (the stream checks the name). Throws inkwire::Error.
std::shared_ptr<asio::ssl::context> client_tls_context(const std::string& ca_file);

}  // namespace inkwire
