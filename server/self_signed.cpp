#include "server/self_signed.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include <openssl/err.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/rand.h>
#include <openssl/x509v3.h>

#include "common/error.hpp"

namespace inkwire::server {
namespace {

template <class T, void (*Free)(T*)>
using Owned = std::unique_ptr<T, decltype([](T* p) { Free(p); })>;

[[noreturn]] void fail(const std::string& what) {
  char reason[256] = "unknown";
  if (const unsigned long code = ERR_get_error()) ERR_error_string_n(code, reason, sizeof reason);
  throw Error("self-signed certificate: " + what + ": " + reason);
}

// This machine's host name, "localhost" and its interfaces' addresses (loopback included).
std::vector<std::string> machine_names() {
  std::vector<std::string> names{"localhost"};
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) == 0 && host[0]) names.insert(names.begin(), host);
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) == 0) {
    for (const ifaddrs* a = list; a; a = a->ifa_next) {
      if (!a->ifa_addr || (a->ifa_addr->sa_family != AF_INET && a->ifa_addr->sa_family != AF_INET6)) continue;
      char text[INET6_ADDRSTRLEN] = {};
      const void* raw = a->ifa_addr->sa_family == AF_INET ? static_cast<const void*>(&reinterpret_cast<const sockaddr_in*>(a->ifa_addr)->sin_addr)
                                                           : static_cast<const void*>(&reinterpret_cast<const sockaddr_in6*>(a->ifa_addr)->sin6_addr);
      if (inet_ntop(a->ifa_addr->sa_family, raw, text, sizeof text) && !std::string(text).starts_with("fe80"))
        names.push_back(text);
    }
    freeifaddrs(list);
  }
  std::sort(names.begin() + 1, names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

bool is_address(const std::string& name) {
  unsigned char buffer[16];
  return inet_pton(AF_INET, name.c_str(), buffer) == 1 || inet_pton(AF_INET6, name.c_str(), buffer) == 1;
}

}  // namespace

SelfSigned make_self_signed(const std::filesystem::path& folder) {
  SelfSigned out{.certificate = folder / "self-signed-certificate.pem", .key = folder / "self-signed-key.pem", .fingerprint = {},
                 .names = machine_names()};
  std::filesystem::create_directories(folder);
  Owned<EVP_PKEY, EVP_PKEY_free> key(EVP_EC_gen("P-256"));
  if (!key) fail("no P-256 key");
  Owned<X509, X509_free> cert(X509_new());
  if (!cert) fail("no certificate");
  X509_set_version(cert.get(), 2);
  unsigned char serial[16];
  if (RAND_bytes(serial, sizeof serial) != 1) fail("no randomness for the serial number");
  serial[0] &= 0x7f;  // a positive number
  Owned<BIGNUM, BN_free> number(BN_bin2bn(serial, sizeof serial, nullptr));
  BN_to_ASN1_INTEGER(number.get(), X509_get_serialNumber(cert.get()));
  X509_gmtime_adj(X509_getm_notBefore(cert.get()), -60);
  X509_gmtime_adj(X509_getm_notAfter(cert.get()), 30L * 24 * 3600);
  X509_set_pubkey(cert.get(), key.get());
  X509_NAME* subject = X509_get_subject_name(cert.get());
  const std::string common_name = "inkwire " + out.names.front();
  X509_NAME_add_entry_by_txt(subject, "CN", MBSTRING_UTF8, reinterpret_cast<const unsigned char*>(common_name.c_str()), -1, -1, 0);
  X509_set_issuer_name(cert.get(), subject);
  std::string alt;
  for (const std::string& name : out.names) alt += (alt.empty() ? "" : ",") + std::string(is_address(name) ? "IP:" : "DNS:") + name;
  X509V3_CTX context;
  X509V3_set_ctx_nodb(&context);
  X509V3_set_ctx(&context, cert.get(), cert.get(), nullptr, nullptr, 0);
  for (const auto& [nid, value] : {std::pair{NID_subject_alt_name, alt}, {NID_basic_constraints, std::string("critical,CA:FALSE")},
                                   {NID_ext_key_usage, std::string("serverAuth")}}) {
    Owned<X509_EXTENSION, X509_EXTENSION_free> extension(X509V3_EXT_conf_nid(nullptr, &context, nid, value.c_str()));
    if (!extension || !X509_add_ext(cert.get(), extension.get(), -1)) fail("cannot name " + value);
  }
  if (!X509_sign(cert.get(), key.get(), EVP_sha256())) fail("cannot sign");

  const auto write = [](const std::filesystem::path& path, auto&& pem) {
    std::FILE* file = std::fopen(path.c_str(), "w");
    if (!file) throw Error("self-signed certificate: cannot write " + path.string());
    const bool written = pem(file);
    std::fclose(file);
    if (!written) fail("cannot write " + path.string());
  };
  const mode_t before = umask(077);  // the key is its owner's alone
  write(out.key, [&](std::FILE* f) { return PEM_write_PrivateKey(f, key.get(), nullptr, nullptr, 0, nullptr, nullptr) == 1; });
  umask(before);
  write(out.certificate, [&](std::FILE* f) { return PEM_write_X509(f, cert.get()) == 1; });

  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (!X509_digest(cert.get(), EVP_sha256(), digest, &length)) fail("no fingerprint");
  for (unsigned int i = 0; i < length; ++i) {
    char pair[4];
    std::snprintf(pair, sizeof pair, "%02X", digest[i]);
    out.fingerprint += (i ? ":" : "") + std::string(pair);
  }
  return out;
}

}  // namespace inkwire::server
