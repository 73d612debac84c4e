#pragma once
// What a server serves: where it listens, where its data lives, and the sessions it creates on
// first start. `inkwire-server --config FILE` reads JSON (README "Running a server"); with no
// file it serves the embedded default: 127.0.0.1, ./inkwire-data, demo sessions built from
// Debian-packaged models.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "protocol/messages.hpp"
#include "common/mesh_import.hpp"
#include "server/call/call_options.hpp"
#include "server/making/making_options.hpp"
#include "server/products/product_store.hpp"

namespace inkwire::server {

struct SessionAsset {
  std::filesystem::path path;
  protocol::AssetKind kind = protocol::AssetKind::Mesh;
};

// A conference session's speaker (SPEC F1-F5): the server analyses these frames and sends the
// expression codes to the session's members, with the neutral photo and its landmarks as assets.
struct FaceSourceConfig {
  std::string source;               // VideoSource spec: camera:N, /dev/videoN, video, folder, pattern
  std::filesystem::path neutral;    // the speaker's neutral photo; empty: the source's first frame
  bool loop = true;                 // start a recorded source again at its end
  double fps = 0;                   // pace of a recorded source; 0: its own
};

struct SessionConfig {
  std::string name;
  protocol::SessionKind kind = protocol::SessionKind::Scene;
  std::string token;  // empty: anyone may join
  std::string editor_token;  // who joins with it is an editor (server/authority.hpp); empty: none
  std::vector<SessionAsset> assets;
  std::string style = "default";
  std::vector<std::string> settings;  // KEY=VALUE
  UpAxis up = UpAxis::Auto;           // which way is up in its mesh files ("up": "y" | "z" | "auto")
  std::optional<FaceSourceConfig> face;  // conference sessions only
  std::optional<ProductSource> product;  // turntable sessions: made (once) when the catalogue lacks the session
};

// TLS on both listeners (SPEC D3): PEM files, read at start.
struct TlsConfig {
  std::filesystem::path certificate;  // the server's certificate chain
  std::filesystem::path key;          // its private key
};

struct ServerConfig {
  std::string host = "127.0.0.1";
  uint16_t port = 7878;  // 0: any free port (logged at start)
  std::filesystem::path data_dir = "inkwire-data";
  std::string name = "inkwire-server";
  size_t queue_bytes = 4 << 20;      // per client, beyond which a client is too slow
  double hello_timeout_seconds = 5;  // for a new connection to say hello
  // After the hello (SPEC D7): a connection that has sent nothing for idle_timeout_seconds, or
  // whose peer has not taken a write for as long, is closed and leaves its session. The server
  // pings a connection it has heard nothing from for heartbeat_seconds, so a quiet healthy client
  // answers long before; clients take 15 s of silence from the server as a dead server, so the
  // heartbeat stays at most 5 s.
  double idle_timeout_seconds = 15;
  double heartbeat_seconds = 5;
  double persist_seconds = 1;        // how often changed session state is written to the catalogue
  // On start, assets no session or product names that were stored longer ago than this are
  // swept (what a killed add-product left); younger ones may belong to one still running.
  double asset_sweep_grace_seconds = 3600;
  size_t max_connections = 4096;             // clients at once, over every transport
  size_t max_connections_per_address = 64;   // clients at once from one IP address
  int join_failures_allowed = 3;             // wrong tokens from one address before its joins are slowed
  bool limit_loopback = false;               // the per-address limits apply to 127.0.0.1 and ::1 too
  std::vector<SessionConfig> sessions;
  // The HTTP listener (WebSocket at /ws, /healthz, /metrics, /): off unless given.
  bool http = false;
  std::string http_host = "127.0.0.1";
  uint16_t http_port = 8080;
  std::vector<std::string> allowed_origins;  // page origins that may open a WebSocket; empty: the server's own
  double http_head_timeout_seconds = 5;      // for a request head to arrive whole
  std::optional<TlsConfig> tls;      // TLS on the native and the HTTP listener
  bool plain_off_loopback = false;   // allow plain listeners off 127.0.0.1 (behind a TLS proxy)
  // Several instances: "redis://HOST:PORT" of the broker they share sessions through (and
  // `name`, unique per instance). Empty: this instance runs alone.
  std::string broker;
  CallOptions call;  // "call_loudest": voices each call member hears at once (K, default 3)
  MakingOptions making;  // "making": rooms and scenes people make themselves

  // The embedded default's demo sessions; models that are not installed are left out.
  static ServerConfig embedded_default();
  // Reads a JSON config over the embedded default. Throws inkwire::Error with the reason.
  static ServerConfig load(const std::filesystem::path& file);
  // The same from the file's text; `origin` names it in refusals.
  static ServerConfig parse(const std::string& text, const std::string& origin);
};

// Parses "HOST:PORT" into the TCP listener or the HTTP one; throws inkwire::Error.
void parse_listen(const std::string& text, ServerConfig& config);
void parse_http(const std::string& text, ServerConfig& config);

}  // namespace inkwire::server
