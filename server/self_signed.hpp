#pragma once
// A throw-away TLS certificate for hosting a call from one's own machine (SPEC F19,
// `inkwire-server --self-signed`): a browser reaches a camera and a microphone only from a secure
// page, and a friend's browser reaches this machine by its name or address. The certificate names
// them all; its SHA-256 fingerprint is what the friend compares before accepting it.
#include <filesystem>
#include <string>
#include <vector>

namespace inkwire::server {

struct SelfSigned {
  std::filesystem::path certificate, key;  // PEM files
  std::string fingerprint;                 // SHA-256, hex pairs joined by ':' (as browsers show it)
  std::vector<std::string> names;          // the host names and addresses it is valid for
};

// Makes a P-256 key and a certificate valid for 30 days into `folder` (created; the key readable by
// its owner alone) for this machine's host name, "localhost" and every address of its interfaces.
// Throws inkwire::Error with OpenSSL's reason.
SelfSigned make_self_signed(const std::filesystem::path& folder);

}  // namespace inkwire::server
