#include "server/config.hpp"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "protocol/framing.hpp"

namespace inkwire::server {
namespace fs = std::filesystem;
using protocol::AssetKind;
using protocol::SessionKind;

namespace {

AssetKind asset_kind_from_string(const std::string& name) {
  for (auto k : {AssetKind::Mesh, AssetKind::Image, AssetKind::Samples, AssetKind::Tween, AssetKind::Landmarks})
    if (protocol::to_string(k) == name) return k;
  throw Error("asset kind '" + name + "' is not mesh, image, samples, tween or landmarks");
}

FaceSourceConfig face_source_from_json(const SessionConfig& session, const nlohmann::json& j) {
  if (session.kind != SessionKind::Conference) throw Error("session '" + session.name + "': only conference sessions take a face source");
  FaceSourceConfig face;
  face.source = j.at("source").get<std::string>();
  face.neutral = j.value("neutral", "");
  face.loop = j.value("loop", true);
  face.fps = j.value("fps", 0.0);
  if (face.source.empty()) throw Error("session '" + session.name + "': face source is empty");
  if (!(face.fps >= 0 && face.fps <= 120)) throw Error("session '" + session.name + "': face fps must be 0 (the source's) to 120");
  return face;
}

ProductSource product_from_json(const SessionConfig& session, const nlohmann::json& j) {
  if (session.kind != SessionKind::Turntable) throw Error("session '" + session.name + "': only turntable sessions take a product");
  ProductSource p;
  p.photos = j.value("photos", "");
  p.mesh = j.value("mesh", "");
  if (p.photos.empty() == p.mesh.empty()) throw Error("session '" + session.name + "': a product is made from \"photos\" or a \"mesh\", one of the two");
  p.photo_options.layout.step_degrees = j.value("step", 0.0f);
  p.photo_options.layout.arc_degrees = j.value("arc", 0.0f);
  p.photo_options.layout.rows = j.value("rows", 0);
  p.photo_options.layout.elevations = j.value("elevations", std::vector<float>{});
  p.photo_options.layout.max_side = j.value("max_side", 2048);
  p.photo_options.matte = j.value("matte", "auto");
  p.mesh_options.samples = j.value("samples", 24);
  p.mesh_options.size = j.value("size", 512);
  p.mesh_options.sphere_level = j.value("sphere", -1);
  return p;
}

MakingOptions making_from_json(const nlohmann::json& j) {
  MakingOptions m;
  if (j.contains("who")) {
    const std::string who = j.at("who").get<std::string>();
    m.who_given = true;
    if (who == "anyone") m.who = MakingPolicy::Anyone;
    else if (who == "token") m.who = MakingPolicy::Token;
    else if (who == "off") m.who = MakingPolicy::Off;
    else throw Error("config: making.who '" + who + "' is not anyone, token or off");
  }
  m.creator_token = j.value("creator_token", "");
  m.max_rooms = j.value("max_rooms", m.max_rooms);
  m.max_rooms_per_address = j.value("max_rooms_per_address", m.max_rooms_per_address);
  m.max_scenes = j.value("max_scenes", m.max_scenes);
  m.max_scenes_per_address = j.value("max_scenes_per_address", m.max_scenes_per_address);
  m.room_idle_seconds = j.value("room_idle_seconds", m.room_idle_seconds);
  m.scene_idle_seconds = j.value("scene_idle_seconds", m.scene_idle_seconds);
  m.max_upload_bytes = j.value("max_upload_bytes", m.max_upload_bytes);
  m.max_triangles = j.value("max_triangles", m.max_triangles);
  m.max_texture_pixels = j.value("max_texture_pixels", m.max_texture_pixels);
  m.import_seconds = j.value("import_seconds", m.import_seconds);
  m.import_memory_bytes = j.value("import_memory_bytes", m.import_memory_bytes);
  m.uploads_per_minute_per_address = j.value("uploads_per_minute_per_address", m.uploads_per_minute_per_address);
  m.max_name_length = j.value("max_name_length", m.max_name_length);
  return m;
}

void check_making(const MakingOptions& m) {
  if (m.who == MakingPolicy::Token && m.creator_token.empty()) throw Error("config: making.who is \"token\" but making.creator_token is empty");
  if (!(m.room_idle_seconds >= 0 && m.room_idle_seconds <= 30 * 86400.0)) throw Error("config: making.room_idle_seconds must be 0..2592000");
  if (!(m.scene_idle_seconds >= 1 && m.scene_idle_seconds <= 365 * 86400.0)) throw Error("config: making.scene_idle_seconds must be 1..31536000");
  if (m.max_upload_bytes < 1024 || m.max_upload_bytes > (1ull << 30)) throw Error("config: making.max_upload_bytes must be 1 KiB..1 GiB");
  if (!(m.import_seconds >= 1 && m.import_seconds <= 3600)) throw Error("config: making.import_seconds must be 1..3600");
  if (m.import_memory_bytes < (64ull << 20)) throw Error("config: making.import_memory_bytes must be at least 64 MiB");
  if (m.max_triangles < 1 || m.max_texture_pixels < 1) throw Error("config: making.max_triangles and max_texture_pixels must be at least 1");
  if (!(m.uploads_per_minute_per_address > 0)) throw Error("config: making.uploads_per_minute_per_address must be above 0");
  if (m.max_name_length < 8 || m.max_name_length > protocol::kMaxName) throw Error("config: making.max_name_length must be 8..64");
}

}  // namespace

void parse_listen(const std::string& text, ServerConfig& config) {
  const size_t colon = text.rfind(':');
  unsigned port = 0;
  char extra = 0;
  if (colon == std::string::npos || colon == 0 || std::sscanf(text.c_str() + colon + 1, "%u%c", &port, &extra) != 1 || port > 65535)
    throw Error("listen address '" + text + "' is not HOST:PORT");
  config.host = text.substr(0, colon);
  config.port = uint16_t(port);
}

void parse_http(const std::string& text, ServerConfig& config) {
  ServerConfig parsed;
  try {
    parse_listen(text, parsed);
  } catch (const Error&) {
    throw Error("http address '" + text + "' is not HOST:PORT");
  }
  config.http = true;
  config.http_host = parsed.host;
  config.http_port = parsed.port;
}

ServerConfig ServerConfig::embedded_default() {
  ServerConfig c;
  // Debian-packaged models: libcgal-demo's meshes (extracted at build time) and assimp-testmodels.
  const fs::path cgal = INKWIRE_MESH_DIR;
  const fs::path truck = "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf";
  auto session = [&](std::string name, SessionKind kind, const fs::path& model, std::string style) {
    SessionConfig s{.name = std::move(name), .kind = kind, .token = "", .editor_token = "", .assets = {}, .style = std::move(style), .settings = {}, .face = {}, .product = {}};
    if (!model.empty() && fs::exists(model)) s.assets.push_back({model, AssetKind::Mesh});
    if (model.empty() || !s.assets.empty()) c.sessions.push_back(std::move(s));
  };
  session("demo", SessionKind::Scene, cgal / "cow.off", "comic-extended");
  session("sketchbook", SessionKind::Scene, cgal / "bull.off", "sketch-pencil");
  // The turntable's product: the textured truck rendered into 24 photos on the server.
  if (fs::exists(truck)) {
    SessionConfig t{.name = "turntable", .kind = SessionKind::Turntable, .token = "", .editor_token = "", .assets = {}, .style = "tween", .settings = {},
                    .face = {}, .product = ProductSource{}};
    t.product->mesh = truck;
    c.sessions.push_back(std::move(t));
  }
  session("conference", SessionKind::Conference, {}, "default");
  return c;
}

ServerConfig ServerConfig::load(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read config '" + file.string() + "'");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse(text, file.string());
}

ServerConfig ServerConfig::parse(const std::string& text, const std::string& origin) {
  ServerConfig c = embedded_default();
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (j.contains("listen")) parse_listen(j.at("listen").get<std::string>(), c);
    if (j.contains("data")) c.data_dir = j.at("data").get<std::string>();
    if (j.contains("name")) c.name = j.at("name").get<std::string>();
    if (j.contains("queue_bytes")) c.queue_bytes = j.at("queue_bytes").get<size_t>();
    if (j.contains("http")) parse_http(j.at("http").get<std::string>(), c);
    if (j.contains("allowed_origins")) c.allowed_origins = j.at("allowed_origins").get<std::vector<std::string>>();
    if (j.contains("broker")) c.broker = j.at("broker").get<std::string>();
    if (j.contains("call_loudest")) c.call.loudest = j.at("call_loudest").get<int>();
    if (j.contains("making")) c.making = making_from_json(j.at("making"));
    if (j.contains("max_connections")) c.max_connections = j.at("max_connections").get<size_t>();
    if (j.contains("max_connections_per_address")) c.max_connections_per_address = j.at("max_connections_per_address").get<size_t>();
    if (j.contains("join_failures_allowed")) c.join_failures_allowed = j.at("join_failures_allowed").get<int>();
    if (j.contains("limit_loopback")) c.limit_loopback = j.at("limit_loopback").get<bool>();
    if (j.contains("plain_off_loopback")) c.plain_off_loopback = j.at("plain_off_loopback").get<bool>();
    if (j.contains("tls")) c.tls = TlsConfig{.certificate = j.at("tls").at("certificate").get<std::string>(), .key = j.at("tls").at("key").get<std::string>()};
    if (j.contains("http_head_timeout_seconds")) c.http_head_timeout_seconds = j.at("http_head_timeout_seconds").get<double>();
    if (j.contains("idle_timeout_seconds")) c.idle_timeout_seconds = j.at("idle_timeout_seconds").get<double>();
    if (j.contains("heartbeat_seconds")) c.heartbeat_seconds = j.at("heartbeat_seconds").get<double>();
    if (j.contains("asset_sweep_grace_seconds")) c.asset_sweep_grace_seconds = j.at("asset_sweep_grace_seconds").get<double>();
    if (j.contains("sessions")) {
      c.sessions.clear();
      for (const auto& s : j.at("sessions")) {
        SessionConfig session;
        session.name = s.at("name").get<std::string>();
        session.kind = protocol::session_kind_from_string(s.value("kind", "scene"));
        session.token = s.value("token", "");
        session.editor_token = s.value("editor_token", "");
        session.style = s.value("style", "default");
        session.settings = s.value("settings", std::vector<std::string>{});
        session.up = parse_up_axis(s.value("up", "auto"));
        for (const auto& a : s.value("assets", nlohmann::json::array()))
          session.assets.push_back({a.at("path").get<std::string>(), asset_kind_from_string(a.value("kind", "mesh"))});
        if (s.contains("face")) session.face = face_source_from_json(session, s.at("face"));
        if (s.contains("product")) session.product = product_from_json(session, s.at("product"));
        if (session.product) session.product->mesh_options.up = session.up;
        c.sessions.push_back(std::move(session));
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw Error("config '" + origin + "': " + e.what());
  }
  if (!(c.http_head_timeout_seconds > 0.05 && c.http_head_timeout_seconds <= 300)) throw Error("config: http_head_timeout_seconds must be 0.05..300");
  if (!(c.asset_sweep_grace_seconds >= 0 && c.asset_sweep_grace_seconds <= 365 * 86400.0))
    throw Error("config: asset_sweep_grace_seconds must be 0..31536000");
  if (!(c.heartbeat_seconds >= 0.1 && c.heartbeat_seconds <= 5)) throw Error("config: heartbeat_seconds must be 0.1..5 (clients take 15 s of silence as a dead server)");
  if (!(c.idle_timeout_seconds >= 2 * c.heartbeat_seconds && c.idle_timeout_seconds <= 3600))
    throw Error("config: idle_timeout_seconds must be at least twice heartbeat_seconds and at most 3600");
  if (c.max_connections < 1 || c.max_connections_per_address < 1) throw Error("config: max_connections and max_connections_per_address must be at least 1");
  if (c.call.loudest < 1 || c.call.loudest > int(protocol::kMaxMembers)) throw Error("config: call_loudest must be 1..64");
  if (c.join_failures_allowed < 0) throw Error("config: join_failures_allowed must be 0 or more");
  if (c.queue_bytes < 2 * protocol::kMaxPayload) throw Error("config: queue_bytes must be at least two frames (262144)");
  check_making(c.making);
  return c;
}

}  // namespace inkwire::server
