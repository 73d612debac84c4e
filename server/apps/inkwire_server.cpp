// inkwire-server: sessions, assets and control messages for thin clients (docs/cli.md, docs/config.md).
#include <algorithm>
#include <csignal>
#include <optional>
#include <cstdio>
#include <iostream>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/mesh_import.hpp"
#include "server/products/product_export.hpp"
#include "server/products/product_store.hpp"
#include "server/self_signed.hpp"
#include "server/server.hpp"
#include "server/session_registry.hpp"
#include "server/session_token.hpp"

using namespace inkwire;

namespace {

// `inkwire-server add-product`: a turntable session NAME in the data folder, from a folder of
// photos or a mesh, made once (the same inputs and settings again find the stored product).
// What a person hosting a call for a friend needs: the link to send and the fingerprint the
// friend's browser will show for the throw-away certificate.
void say_join_links(const server::ServerConfig& config, uint16_t port, const server::SelfSigned& certificate) {
  std::string call = "conference";
  for (const auto& s : config.sessions)
    if (s.kind == protocol::SessionKind::Conference) {
      call = s.name;
      break;
    }
  const bool everywhere = config.http_host == "0.0.0.0" || config.http_host == "::";
  std::cout << "inkwire-server: TLS with a throw-away certificate, SHA-256 fingerprint\n  " << certificate.fingerprint
            << "\n(your friend's browser warns of it once: the fingerprint it shows must be this one)\njoin links:\n";
  for (const std::string& name : certificate.names) {
    if (everywhere ? (name == "localhost" || name == "127.0.0.1" || name == "::1") : name != config.http_host) continue;
    const bool v6 = name.find(':') != std::string::npos;
    std::cout << "  https://" << (v6 ? "[" + name + "]" : name) << ":" << port << "/call/" << call << "\n";
  }
  if (!everywhere && std::find(certificate.names.begin(), certificate.names.end(), config.http_host) == certificate.names.end())
    std::cout << "  https://" << config.http_host << ":" << port << "/call/" << call << "\n";
  std::cout << std::flush;
}

// The product named `name` in the store's sessions; throws when there is none.
protocol::Snapshot stored_product(const server::AssetStore& store, const std::string& name) {
  for (const auto& s : store.sessions())
    if (s.state.session == name && s.state.kind == protocol::SessionKind::Turntable) return s.state;
  throw Error("no product named '" + name + "' in " + store.dir().string() + " (make it with add-product)");
}

// `inkwire-server export-product NAME DIR` (and add-product --export DIR): the product as static
// files, and the snippet a shop pastes.
void export_to(const server::AssetStore& store, const std::string& name, const std::filesystem::path& dir) {
  const server::ExportSummary summary = server::export_product(store, stored_product(store, name), dir);
  std::printf("exported product '%s' to %s: %zu files written (%llu bytes), %zu already there; a first view fetches %llu bytes of it\n"
              "Put the folder on any static host or object store as it is (deploy/static-hosting.md says which headers each file "
              "wants) and paste, with its address for PRODUCT-URL:\n"
              "  <script type=\"module\" src=\"PRODUCT-URL/inkwire.js\"></script>\n"
              "  <inkwire-turntable src=\"PRODUCT-URL/product.json\" style=\"width:600px;height:450px\"></inkwire-turntable>\n",
              name.c_str(), dir.c_str(), summary.written, static_cast<unsigned long long>(summary.bytes_written), summary.kept,
              static_cast<unsigned long long>(summary.first_view_bytes));
}

int add_product(const std::string& name, const server::ProductSource& source, const std::string& data, const std::string& editor_token,
                const std::filesystem::path& export_dir) {
  if (name.empty() || name.size() > protocol::kMaxName ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") != std::string::npos)
    throw Error("product name '" + name + "' must be 1-64 letters, digits, - _ .");
  server::AssetStore store(data.empty() ? "inkwire-data" : data);
  const bool terminal = isatty(fileno(stdout));
  bool made = false;
  protocol::Snapshot state = server::find_or_make_product(store, source, name, [&](int done, int total, const std::string& line) {
    if (done == 0) {  // a note, not a pair (why there are no mattes, how much exposure was evened)
      std::printf("note: %s\n", line.c_str());
      return;
    }
    // One line per pair, with a bar on a terminal.
    std::string bar;
    if (terminal && total > 0) bar = "[" + std::string(size_t(20 * done / total), '#') + std::string(size_t(20 - 20 * done / total), '.') + "] ";
    std::printf("%spair %d/%d %s\n", bar.c_str(), done, total, line.c_str());
    std::fflush(stdout);
  }, &made);
  // Re-adding under a name keeps nothing of the old session but its tokens (a new editor token
  // replaces the old one).
  std::string token, editor = server::hash_token(editor_token);
  for (const auto& s : store.sessions())
    if (s.state.session == name) token = s.token, editor = editor_token.empty() ? s.editor_token : editor;
  store.save_session({.token = token, .editor_token = editor, .state = state});
  // What a customer fetches to turn it (photos, mattes, tween data), and each zoom level apart
  // (fetched only zoomed in, a few photos at a time).
  const size_t samples = state.product.directions.size();
  uint64_t first = 0;
  for (const auto& a : state.assets)
    if (a.kind != protocol::AssetKind::Zoom) first += a.size;
  const std::vector<uint64_t> levels = server::zoom_level_bytes(state);
  std::string zoom;
  for (size_t l = 0; l < levels.size(); ++l)
    zoom += "; zoom level " + std::to_string(state.product.levels[l].width) + "x" + std::to_string(state.product.levels[l].height) + ": " +
            std::to_string(levels[l]) + " bytes";
  std::printf("%s product '%s': %zu photos %dx%d, %u tween cells, %llu bytes%s; in %s\n", made ? "stored" : "already stored:",
              name.c_str(), samples, state.product.width, state.product.height, unsigned(state.product.cells),
              static_cast<unsigned long long>(first), zoom.c_str(), store.dir().c_str());
  std::printf("Served by inkwire-server (--http HOST:PORT), paste:\n"
              "  <script type=\"module\" src=\"http://HOST:PORT/inkwire.js\"></script>\n"
              "  <inkwire-turntable server=\"ws://HOST:PORT/ws\" session=\"%s\" style=\"width:600px;height:450px\"></inkwire-turntable>\n",
              name.c_str());
  if (!export_dir.empty()) export_to(store, name, export_dir);
  return 0;
}

// `inkwire-server add-scene NAME --mesh FILE`: a kept scene of the model in the data folder (its
// model replaced if the scene is there already), which a running server takes up within a second.
int add_scene(const std::string& name, const std::filesystem::path& mesh, const std::string& style, const std::vector<std::string>& settings,
              const std::string& editor_token, UpAxis up, const std::string& data) {
  if (name.empty() || name.size() > protocol::kMaxName ||
      name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") != std::string::npos)
    throw Error("scene name '" + name + "' must be 1-64 letters, digits, - _ .");
  server::AssetStore store(data.empty() ? "inkwire-data" : data);
  std::optional<server::StoredSession> stored;
  for (auto& s : store.sessions())
    if (s.state.session == name) stored = std::move(s);
  if (stored && (stored->state.kind != protocol::SessionKind::Scene || !stored->state.product.directions.empty()))
    throw Error("'" + name + "' is a " + protocol::to_string(stored->state.kind) + " session, not a scene");
  const protocol::AssetAnnounce model = server::store_model(store, mesh, up);  // refuses what no client could draw, storing nothing
  if (!stored) stored = server::StoredSession{.token = "", .editor_token = "", .state = server::fresh_session_state(name, protocol::SessionKind::Scene, "default")};
  if (!style.empty()) stored->state.style = {.renderer = style, .settings = settings};
  if (!editor_token.empty()) stored->editor_token = server::hash_token(editor_token);
  stored->state.assets = {model};
  ++stored->state.revision;
  stored->maker = server::MadeBy::Command;
  stored->kept = true;
  store.save_session(*stored);
  std::printf("stored scene '%s': %s (%llu bytes), style %s; in %s. Its page: http://HOST:PORT/scene/%s\n", name.c_str(), model.name.c_str(),
              static_cast<unsigned long long>(model.size), stored->state.style.renderer.c_str(), store.dir().c_str(), name.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string listen, http, data, config_file, broker, name;
  bool quiet = false;
  CLI::App app{"inkwire-server: serves Inkwire sessions (shared scenes, turntables, conferences) to thin clients"};
  app.add_option("--listen", listen, "HOST:PORT to listen on (default 127.0.0.1:7878; port 0 picks a free one)");
  app.add_option("--http", http, "HOST:PORT for HTTP: WebSocket clients at /ws, /healthz, /metrics, the session index at /");
  app.add_option("--data", data, "data folder: asset files and the SQLite catalogue (default ./inkwire-data)");
  app.add_option("--config", config_file, "JSON config: listen, data, http, sessions and more (every key in docs/config.md)");
  app.add_option("--broker", broker, "redis://HOST:PORT: share sessions with the other instances on that Redis (each with its own --name)");
  app.add_option("--name", name, "this instance's name, unique among the instances sharing a broker (default inkwire-server)");
  app.add_flag("--quiet", quiet, "log warnings and errors only");
  bool self_signed = false;
  app.add_flag("--self-signed", self_signed,
               "TLS with a throw-away certificate for this machine's names and addresses (kept in DATA/tls): prints the join link and the "
               "certificate's fingerprint, for hosting a call for a friend with --http 0.0.0.0:PORT");

  std::string product_name, product_data, editor_token;
  server::ProductSource source;
  CLI::App* add = app.add_subcommand("add-product", "make a turntable session NAME from a folder of photos or a mesh, once");
  add->add_option("name", product_name, "the session's name, as clients and pages ask for it")->required();
  auto* photos = add->add_option("--photos", source.photos, "folder of photos taken around the object, in file-name order");
  auto* mesh = add->add_option("--mesh", source.mesh, "a mesh rendered into samples on a ring instead");
  photos->excludes(mesh);
  PhotoLayout& layout = source.photo_options.layout;
  add->add_option("--step", layout.step_degrees, "degrees the view turns from one photo to the next, negative if the turntable turned the other way (default: a full turn, each step found from the photos)")->needs(photos);
  add->add_option("--arc", layout.arc_degrees, "degrees from the first photo to the last of a row (default: a full turn)")->needs(photos);
  add->add_option("--rows", layout.rows, "rings of photos at several camera heights, the files in order, lowest first (sub-folders row1, row2, ... need no --rows)")->needs(photos);
  add->add_option("--elevations", layout.elevations, "the rows' camera heights in degrees, lowest first, comma-separated (default: level, then 15 degrees apart)")
      ->delimiter(',')->needs(photos);
  add->add_option("--max-side", layout.max_side, "photos are kept at most this many pixels a side, the finest zoom level (32..2048, default 2048); they are matched and first shown at most 512")->needs(photos);
  add->add_option("--matte", source.photo_options.matte, "auto: key a plain backdrop when there is one; key: refuse if not; none")
      ->needs(photos);
  add->add_option("--shape", source.photo_options.shape,
                  "auto (default): with photos all round, find the camera and the object's shape from their silhouettes (the mattes, "
                  "filled to their outlines where they carve nothing whole, or cut from a backdrop that is not plain) and take the "
                  "control points of a pair (or a triangle between rows) from the shape where the photos agree better under it "
                  "than under the matches; off: "
                  "matched points only")
      ->check(CLI::IsMember({"auto", "off"}))
      ->needs(photos);
  add->add_option("--samples", source.mesh_options.samples, "samples on the ring (default 24)")->needs(mesh);
  add->add_option_function<std::string>("--up", [&](const std::string& up) { source.mesh_options.up = parse_up_axis(up); },
                                        "which axis is up in the mesh file: y, z or auto (what the file says)")
      ->check(CLI::IsMember({"auto", "y", "z"}))->needs(mesh);
  add->add_option("--size", source.mesh_options.size, "sample images are this many pixels square (default 512)")->needs(mesh);
  add->add_option("--sphere", source.mesh_options.sphere_level,
                  "samples on a geodesic sphere instead of a ring: 0, 1 or 2 (12, 42, 162 samples), views from any side")
      ->needs(mesh);
  add->add_option("--data", product_data, "data folder (default ./inkwire-data)");
  add->add_option("--editor-token", editor_token,
                  "who joins the product with this token may present it and change its style; visitors only turn their own view "
                  "(without it the product keeps the editor token it had; one never given has no editor)");
  std::filesystem::path export_dir;
  add->add_option("--export", export_dir, "also write the product as static files into this folder (as export-product does)");
  CLI::App* exporting = app.add_subcommand("export-product", "write product NAME as static files for any static host or CDN: "
                                                              "photos, mattes and tween cells under their hashes, product.json, the element");
  exporting->add_option("name", product_name, "the product's session name")->required();
  exporting->add_option("dir", export_dir, "the folder to write (an earlier export there is updated: only what changed is added)")->required();
  exporting->add_option("--data", product_data, "data folder (default ./inkwire-data)");
  CLI::App* removing = app.add_subcommand("remove-product", "take product NAME out of the data folder: a running server stops serving it within "
                                                             "seconds (its visitors are told), its files are swept at a later start");
  removing->add_option("name", product_name, "the product's session name")->required();
  removing->add_option("--data", product_data, "data folder (default ./inkwire-data)");
  std::string scene_name, scene_data, scene_style, scene_editor_token, scene_up = "auto";
  std::filesystem::path scene_mesh;
  std::vector<std::string> scene_settings;
  CLI::App* adding_scene = app.add_subcommand("add-scene", "make (or replace the model of) a kept scene NAME from a model file; a running server "
                                                            "takes it up within a second");
  adding_scene->add_option("name", scene_name, "the scene's name, as clients and pages ask for it")->required();
  adding_scene->add_option("--mesh", scene_mesh, "the model: any format the importer reads (a glTF with its files, OBJ with MTL, PLY, OFF, STL, 3DS, FBX...)")
      ->required();
  adding_scene->add_option("--style", scene_style, "its style (default: default, or what the scene had)");
  adding_scene->add_option("--settings", scene_settings, "KEY=VALUE settings for --style");
  adding_scene->add_option("--editor-token", scene_editor_token, "who joins with this token steers the scene; the others follow");
  adding_scene->add_option("--up", scene_up, "which axis is up in the model file: y, z or auto")->check(CLI::IsMember({"auto", "y", "z"}));
  adding_scene->add_option("--data", scene_data, "data folder (default ./inkwire-data)");
  CLI::App* keeping_scene = app.add_subcommand("keep-scene", "keep scene NAME (one a visitor uploaded) however long it goes unvisited; a running "
                                                             "server takes it up within a second");
  keeping_scene->add_option("name", scene_name, "the scene's name")->required();
  keeping_scene->add_option("--data", scene_data, "data folder (default ./inkwire-data)");
  CLI::App* removing_scene = app.add_subcommand("remove-scene", "take scene NAME out of the data folder: a running server stops serving it within a "
                                                                 "second (its members are told)");
  removing_scene->add_option("name", scene_name, "the scene's name")->required();
  removing_scene->add_option("--data", scene_data, "data folder (default ./inkwire-data)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (adding_scene->parsed()) {
    try {
      if (quiet) set_log_level(LogLevel::Warn);
      return add_scene(scene_name, scene_mesh, scene_style, scene_settings, scene_editor_token, parse_up_axis(scene_up), scene_data);
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server add-scene: " << e.what() << "\n";
      return 1;
    }
  }
  if (keeping_scene->parsed()) {
    try {
      server::AssetStore store(scene_data.empty() ? "inkwire-data" : scene_data);
      std::optional<server::StoredSession> scene;
      for (auto& s : store.sessions())
        if (s.state.session == scene_name && s.state.kind == protocol::SessionKind::Scene) scene = std::move(s);
      if (!scene) throw Error("no scene named '" + scene_name + "' in " + store.dir().string());
      scene->kept = true;
      store.save_session(*scene);
      std::printf("scene '%s' is kept\n", scene_name.c_str());
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server keep-scene: " << e.what() << "\n";
      return 1;
    }
  }
  if (removing_scene->parsed()) {
    try {
      server::AssetStore store(scene_data.empty() ? "inkwire-data" : scene_data);
      bool scene = false;
      for (const auto& s : store.sessions()) scene |= s.state.session == scene_name && s.state.kind == protocol::SessionKind::Scene;
      if (!scene || !store.remove_session(scene_name)) throw Error("no scene named '" + scene_name + "' in " + store.dir().string());
      std::printf("removed scene '%s' from %s (a scene the config names is made again at the next start)\n", scene_name.c_str(), store.dir().c_str());
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server remove-scene: " << e.what() << "\n";
      return 1;
    }
  }
  if (removing->parsed()) {
    try {
      server::AssetStore store(product_data.empty() ? "inkwire-data" : product_data);
      if (!store.remove_product(product_name)) throw Error("no product named '" + product_name + "' in " + store.dir().string());
      std::printf("removed product '%s' from %s (a product the config names is made again at the next start)\n", product_name.c_str(),
                  store.dir().string().c_str());
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server remove-product: " << e.what() << "\n";
      return 1;
    }
  }
  if (exporting->parsed()) {
    try {
      if (quiet) set_log_level(LogLevel::Warn);
      export_to(server::AssetStore(product_data.empty() ? "inkwire-data" : product_data), product_name, export_dir);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server export-product: " << e.what() << "\n";
      return 1;
    }
  }
  if (add->parsed()) {
    try {
      if (source.photos.empty() && source.mesh.empty()) throw Error("add-product needs --photos DIR or --mesh FILE");
      if (quiet) set_log_level(LogLevel::Warn);
      return add_product(product_name, source, product_data, editor_token, export_dir);
    } catch (const std::exception& e) {
      std::cerr << "inkwire-server add-product: " << e.what() << "\n";
      return 1;
    }
  }
  try {
    if (quiet) set_log_level(LogLevel::Warn);
    server::ServerConfig config = config_file.empty() ? server::ServerConfig::embedded_default() : server::ServerConfig::load(config_file);
    if (!listen.empty()) server::parse_listen(listen, config);
    if (!http.empty()) server::parse_http(http, config);
    if (!data.empty()) config.data_dir = data;
    if (!broker.empty()) config.broker = broker;
    if (!name.empty()) config.name = name;
    std::optional<server::SelfSigned> certificate;
    if (self_signed) {
      if (!config.http) throw Error("--self-signed needs --http HOST:PORT: browsers join a call over HTTPS");
      certificate = server::make_self_signed(config.data_dir / "tls");
      config.tls = server::TlsConfig{.certificate = certificate->certificate, .key = certificate->key};
      log_info("self-signed", {{"fingerprint", certificate->fingerprint}, {"names", certificate->names}});
    }
    // A client vanishing mid-write must not kill the server.
    std::signal(SIGPIPE, SIG_IGN);
    asio::io_context io(1);
    server::Server server(io, config);
    asio::signal_set signals(io, SIGINT, SIGTERM);
    signals.async_wait([&](std::error_code, int signal) {
      log_info("signal", {{"signal", signal}});
      server.stop();
    });
    server.start();
    if (certificate) say_join_links(config, server.http_port(), *certificate);
    io.run();
    log_info("stopped");
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "inkwire-server: " << e.what() << "\n";
    return 1;
  }
}
