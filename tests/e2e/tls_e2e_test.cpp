// TLS on the server's listeners (SPEC D3), end to end on 127.0.0.1 with a throw-away
// certificate: a client that trusts it joins and follows a change; a plain-TCP client on the
// TLS port is refused cleanly while the server carries on; a client that does not trust the
// certificate, or reaches the server under a name the certificate lacks, fails saying why;
// plain listeners off this machine are refused at start. Skipped with a message without the
// openssl program (Debian package openssl).
#include <asio.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/net/session_client.hpp"
#include "protocol/net/byte_stream.hpp"
#include "e2e_support.hpp"
#include "../unit/test_data.hpp"

using namespace inkwire;
using namespace inkwire::e2e;
namespace fs = std::filesystem;

namespace {

const fs::path kOpenssl = "/usr/bin/openssl";

// A self-signed certificate for `name` (an IP address) and its key, as an operator would make
// one for a test (docs/deploy.md).
void make_certificate(const fs::path& dir, const std::string& stem, const std::string& name) {
  Process openssl(kOpenssl.string(), {"req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-days", "1",
                                      "-subj", "/CN=" + name, "-addext", "subjectAltName=IP:" + name,
                                      "-keyout", (dir / (stem + ".key")).string(), "-out", (dir / (stem + ".pem")).string()},
                  dir / (stem + "-openssl.log"));
  ASSERT_EQ(openssl.wait(), 0) << openssl.output();
}

nlohmann::json tls_config(const fs::path& dir) {
  return {{"http", "127.0.0.1:0"}, {"tls", {{"certificate", (dir / "server.pem").string()}, {"key", (dir / "server.key").string()}}},
          {"sessions", {{{"name", "room"}, {"kind", "scene"}, {"assets", nlohmann::json::array()}}}}};
}

// Whether a TLS handshake with the HTTP listener succeeds offering only `suites` (TLS 1.2 names)
// or, with `tls13`, TLS 1.3 alone; what the server then answers to GET /healthz, or "".
std::string handshake_with(int port, const std::string& certificate, const std::string& suites, bool tls13 = false) {
  asio::io_context io;
  auto trust = client_tls_context(certificate);
  SSL_CTX* ctx = trust->native_handle();
  SSL_CTX_set_min_proto_version(ctx, tls13 ? TLS1_3_VERSION : TLS1_2_VERSION);
  SSL_CTX_set_max_proto_version(ctx, tls13 ? TLS1_3_VERSION : TLS1_2_VERSION);
  if (!tls13 && SSL_CTX_set_cipher_list(ctx, suites.c_str()) != 1) return "";
  ByteStream stream(asio::ip::tcp::socket(io), *trust);
  stream.socket().connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  std::error_code ec;
  stream.tls_stream()->handshake(asio::ssl::stream_base::client, ec);
  if (ec) return "";
  asio::write(*stream.tls_stream(), asio::buffer(std::string("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n")), ec);
  std::string answer;
  asio::read(*stream.tls_stream(), asio::dynamic_buffer(answer), ec);
  return answer;
}

}  // namespace

class TlsE2ETest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kOpenssl)) GTEST_SKIP() << kOpenssl << " is missing (Debian package openssl)";
  }
};

TEST_F(TlsE2ETest, AClientTrustingTheCertificateJoinsAndPlainTcpIsRefusedCleanly) {
  const fs::path dir = output_dir("tls");
  make_certificate(dir, "server", "127.0.0.1");
  ServerUnderTest server(dir, tls_config(dir));

  SessionClient a(server.address(), "a", client_tls_context((dir / "server.pem").string()));
  SessionClient b(server.address(), "b", client_tls_context((dir / "server.pem").string()));
  a.join("room", "");
  b.join("room", "");
  a.send(protocol::StyleChange{.renderer = "comic", .settings = {}});
  EXPECT_TRUE(eventually([&] { return b.state().style.renderer == "comic"; })) << "a change did not cross over TLS";

  // Plain TCP on the TLS port: no hang, no crash, a reason on both sides.
  const std::string plain = test::error_of([&] { SessionClient p(server.address(), "plain"); });
  EXPECT_FALSE(plain.empty()) << "a plain-TCP client was served on the TLS port";
  EXPECT_TRUE(eventually([&] { return !log_events(server.process().output(), "tls-handshake-failed").empty(); })) << server.process().output();

  // A client that trusts other certificates refuses this server.
  make_certificate(dir, "other", "127.0.0.1");
  const std::string untrusted = test::error_of([&] { SessionClient u(server.address(), "untrusted", client_tls_context((dir / "other.pem").string())); });
  EXPECT_NE(untrusted.find("TLS"), std::string::npos) << untrusted;
  std::printf("  refused: plain TCP: %s\n  untrusted: %s\n", plain.c_str(), untrusted.c_str());
  // ... and so does one that reached it under a name the certificate does not carry.
  const std::string wrong_name = test::error_of([&] {
    SessionClient w("localhost:" + server.address().substr(server.address().rfind(':') + 1), "wrong-name", client_tls_context((dir / "server.pem").string()));
  });
  EXPECT_NE(wrong_name.find("TLS"), std::string::npos) << wrong_name;
  std::printf("  wrong name: %s\n", wrong_name.c_str());

  // The HTTP listener speaks TLS too (https://, wss://), and a plain request there gets nothing.
  {
    asio::io_context io;
    auto trust = client_tls_context((dir / "server.pem").string());
    ByteStream stream(asio::ip::tcp::socket(io), *trust);
    stream.socket().connect({asio::ip::make_address("127.0.0.1"), uint16_t(http_port(server))});
    stream.tls_stream()->set_verify_callback(asio::ssl::host_name_verification("127.0.0.1"));
    stream.tls_stream()->handshake(asio::ssl::stream_base::client);
    asio::write(*stream.tls_stream(), asio::buffer(std::string("GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n")));
    std::string answer;
    std::error_code ec;
    asio::read(*stream.tls_stream(), asio::dynamic_buffer(answer), ec);
    EXPECT_NE(answer.find("200 OK"), std::string::npos) << answer;
    EXPECT_EQ(http_get(http_port(server), "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK"), std::string::npos);
  }

  // Everyone else carries on.
  b.send(protocol::StyleChange{.renderer = "hatching", .settings = {}});
  EXPECT_TRUE(eventually([&] { return a.state().style.renderer == "hatching"; }));
  EXPECT_TRUE(server.process().running());
}

TEST_F(TlsE2ETest, PlainListenersOffThisMachineAreRefusedAtStartWithTheReason) {
  const fs::path dir = output_dir("tls-required");
  std::ofstream(dir / "server.json") << nlohmann::json{{"sessions", nlohmann::json::array()}}.dump();
  Process server("inkwire-server", {"--listen", "0.0.0.0:0", "--data", (dir / "data").string(), "--config", (dir / "server.json").string()}, dir / "server.log");
  EXPECT_EQ(server.wait(), 1);
  EXPECT_NE(server.output().find("reachable from other machines"), std::string::npos) << server.output();
  EXPECT_FALSE(fs::exists(dir / "data")) << "the refused server created its data folder";
}

// Hosting a call for a friend is one command (SPEC F19): --self-signed makes a certificate for this
// machine's names and addresses, prints the join link and the fingerprint a friend's browser shows,
// and both listeners speak TLS with it (a client trusting that certificate joins at 127.0.0.1).
TEST_F(TlsE2ETest, SelfSignedMakesACertificatePrintsTheJoinLinkAndItsFingerprintAndServesWithIt) {
  const fs::path dir = output_dir("tls-self-signed");
  std::ofstream(dir / "server.json") << nlohmann::json{{"sessions", {{{"name", "friends"}, {"kind", "conference"}}}}}.dump();
  Process server("inkwire-server", {"--listen", "127.0.0.1:0", "--http", "127.0.0.1:0", "--data", (dir / "data").string(), "--config",
                                    (dir / "server.json").string(), "--self-signed"}, dir / "server.log");
  ASSERT_TRUE(eventually([&] { return server.output().find("/call/friends") != std::string::npos || !server.running(); })) << server.output();
  const std::string out = server.output();
  const fs::path certificate = dir / "data" / "tls" / "self-signed-certificate.pem";
  ASSERT_TRUE(fs::exists(certificate)) << out;
  EXPECT_EQ(fs::status(dir / "data" / "tls" / "self-signed-key.pem").permissions() & (fs::perms::group_all | fs::perms::others_all), fs::perms::none)
      << "the key is readable by others";
  // The fingerprint printed is the certificate's (as openssl computes it).
  Process fingerprint(kOpenssl.string(), {"x509", "-in", certificate.string(), "-noout", "-fingerprint", "-sha256"}, dir / "fingerprint.log");
  ASSERT_EQ(fingerprint.wait(), 0);
  const std::string printed = fingerprint.output().substr(fingerprint.output().find('=') + 1, 95);
  EXPECT_NE(out.find(printed), std::string::npos) << "fingerprint " << printed << " not in: " << out;
  int tcp = 0, http = 0;
  for (const auto& j : log_events(out, "listening")) tcp = j.value("port", 0);
  for (const auto& j : log_events(out, "http-listening")) http = j.value("port", 0);
  EXPECT_NE(out.find("https://127.0.0.1:" + std::to_string(http) + "/call/friends"), std::string::npos) << out;
  // A client that trusts it reaches the server by address: the certificate names 127.0.0.1.
  SessionClient member("127.0.0.1:" + std::to_string(tcp), "friend", client_tls_context(certificate.string()));
  EXPECT_NO_THROW(member.join("friends", ""));
}

// TLS as the usual profiles have it (issue: a scanner faulted the CBC suites): TLS 1.2 with ECDHE
// and AES-GCM or ChaCha20 only, TLS 1.3, and HSTS on every HTTPS reply.
TEST_F(TlsE2ETest, OnlyAeadSuitesAreOfferedAndHttpsRepliesCarryHsts) {
  const fs::path dir = output_dir("tls-suites");
  make_certificate(dir, "server", "127.0.0.1");
  ServerUnderTest server(dir, tls_config(dir));
  const int port = http_port(server);
  const std::string certificate = (dir / "server.pem").string();
  for (const std::string suite : {"ECDHE-ECDSA-AES128-GCM-SHA256", "ECDHE-ECDSA-AES256-GCM-SHA384", "ECDHE-ECDSA-CHACHA20-POLY1305"}) {
    const std::string answer = handshake_with(port, certificate, suite);
    EXPECT_NE(answer.find("200 OK"), std::string::npos) << suite << " is refused";
    EXPECT_NE(answer.find("Strict-Transport-Security: max-age="), std::string::npos) << "no HSTS: " << answer;
  }
  for (const std::string suite : {"ECDHE-ECDSA-AES128-SHA", "ECDHE-ECDSA-AES256-SHA", "ECDHE-ECDSA-AES128-SHA256", "ECDHE-ECDSA-AES256-SHA384"})
    EXPECT_EQ(handshake_with(port, certificate, suite), "") << "the CBC suite " << suite << " is offered";
  EXPECT_NE(handshake_with(port, certificate, "", true).find("200 OK"), std::string::npos) << "TLS 1.3 is refused";
}
