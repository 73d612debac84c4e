#include "server/web/uploads.hpp"

#include <charconv>
#include <cmath>

#include <asio/experimental/as_tuple.hpp>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "server/making/import_process.hpp"
#include "server/making/multipart.hpp"
#include "server/relay/relay.hpp"
#include "server/server.hpp"
#include "server/session_token.hpp"
#include "server/web/http_reply.hpp"
#include "server/web/http_request.hpp"

namespace inkwire::server {
namespace {

namespace fs = std::filesystem;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
// An upload that sends nothing for this long is cut off: a stalled sender holds no socket.
constexpr auto kStall = std::chrono::seconds(15);

std::string json_reply(int status, const nlohmann::json& body, const std::string& headers = "") {
  return http_reply(status, "application/json", body.dump() + "\n", headers);
}
std::string refusal(int status, const std::string& reason, const std::string& headers = "") { return json_reply(status, {{"error", reason}}, headers); }

// The upload's folder, made fresh and removed with everything in it when the upload is over.
struct UploadFolder {
  fs::path path;
  explicit UploadFolder(const fs::path& data) : path(data / "uploads" / random_hex(12)) { fs::create_directories(path); }
  ~UploadFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// The body (after `early`, the bytes that came with the head) into `files`, with a watchdog
// that cuts the socket off when the sender stalls. Empty, or why the body was refused.
asio::awaitable<std::string> read_body(ByteStream& socket, uint64_t length, std::string early, MultipartFiles& files) {
  uint64_t received = 0;
  try {
    if (early.size() > length) early.resize(length);
    files.feed(early);
    received = early.size();
  } catch (const Error& e) {
    co_return e.what();
  }
  auto heard = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
  auto stalled = std::make_shared<bool>(false);
  auto watchdog = std::make_shared<asio::steady_timer>(socket.get_executor());
  std::function<void()> watch = [&socket, heard, stalled, watchdog, &watch] {
    watchdog->expires_after(std::chrono::seconds(1));
    watchdog->async_wait([&socket, heard, stalled, watchdog, &watch](std::error_code ec) {
      if (ec) return;
      if (std::chrono::steady_clock::now() - *heard > kStall) {
        // The read waiting for it ends; the socket stays open for the reply saying why.
        *stalled = true;
        std::error_code ignored;
        socket.socket().cancel(ignored);
        return;
      }
      watch();
    });
  };
  watch();
  std::vector<char> buffer(64 * 1024);
  std::string problem;
  while (received < length) {
    auto [ec, n] = co_await socket.async_read_some(asio::buffer(buffer.data(), size_t(std::min<uint64_t>(buffer.size(), length - received))), no_throw);
    if (ec) {
      problem = *stalled ? "the upload stalled (nothing came for 15 s)" : "the upload ended before its " + std::to_string(length) + " bytes";
      break;
    }
    *heard = std::chrono::steady_clock::now();
    received += n;
    try {
      files.feed(std::string_view(buffer.data(), n));
    } catch (const Error& e) {
      problem = e.what();
      break;
    }
  }
  watchdog->cancel();
  if (problem.empty()) {
    try {
      files.finish();
    } catch (const Error& e) {
      problem = e.what();
    }
  }
  co_return problem;
}

}  // namespace

asio::awaitable<std::string> receive_upload(Server& server, ByteStream& socket, const Request& request, const std::string& path, std::string early,
                                            const std::string& address) {
  SessionMaker& maker = server.maker();
  const MakingOptions& options = maker.options();
  // Which upload: a new scene, or a running scene's new model (by its editor).
  std::shared_ptr<Session> scene;
  if (path != "/scenes") {
    const std::string name = path.substr(8, path.size() - 8 - 6);  // "/scenes/" NAME "/model"
    if (!path.starts_with("/scenes/") || !path.ends_with("/model") || name.empty()) co_return refusal(404, "no such upload address: POST /scenes or /scenes/NAME/model");
    scene = server.find_session(name);
    if (!scene || scene->state().kind != protocol::SessionKind::Scene || !scene->state().product.directions.empty())
      co_return refusal(404, "no scene " + name);
    if (scene->role_of(request.header("x-inkwire-editor-key")) != Role::Editor || scene->stored().editor_token.empty()) {
      maker.count_refusal("not-editor");
      co_return refusal(403, "only the scene's editor may replace its model");
    }
  } else if (std::string why, key; !(why = maker.may_make_scene(request.header("x-inkwire-creator-token"), address, &key)).empty()) {
    maker.count_refusal(key);
    co_return refusal(403, why);
  }
  // Refused before the body is read: no length, too long, not multipart.
  const std::string length_text = request.header("content-length");
  uint64_t length = 0;
  const auto [end, parsed] = std::from_chars(length_text.data(), length_text.data() + length_text.size(), length);
  if (length_text.empty() || parsed != std::errc() || end != length_text.data() + length_text.size()) {
    maker.count_refusal("no-length");
    co_return refusal(411, "an upload says its Content-Length");
  }
  if (length > options.max_upload_bytes) {
    maker.count_refusal("size");
    co_return refusal(413, "the upload is " + std::to_string(length >> 20) + " MiB; this server takes at most " + std::to_string(options.max_upload_bytes >> 20) + " MiB");
  }
  std::string boundary;
  try {
    boundary = multipart_boundary(request.header("content-type"));
  } catch (const Error& e) {
    maker.count_refusal("malformed");
    co_return refusal(415, e.what());
  }
  double retry_after = 0;
  if (const std::string busy = maker.take_upload(address, SessionMaker::Clock::now(), &retry_after); !busy.empty())
    co_return refusal(429, busy, "Retry-After: " + std::to_string(int(std::ceil(retry_after))) + "\r\n");
  struct Done {
    SessionMaker& maker;
    const std::string& address;
    ~Done() { maker.upload_done(address); }
  } done{maker, address};
  std::optional<UploadFolder> folder;
  try {
    folder.emplace(server.config().data_dir);
  } catch (const std::exception& e) {
    co_return refusal(500, std::string("cannot take uploads now: ") + e.what());
  }
  fs::create_directories(folder->path / "files");
  MultipartFiles files(boundary, folder->path / "files");
  if (const std::string problem = co_await read_body(socket, length, std::move(early), files); !problem.empty()) {
    maker.count_refusal("malformed");
    log_info("upload-refused", {{"peer", address}, {"reason", problem}});
    co_return refusal(400, problem);
  }
  // Imports run a few at a time (each may take import_memory_bytes): an upload read whole waits
  // its turn, for as long as two imports may take, then is refused.
  const auto waiting_since = std::chrono::steady_clock::now();
  while (!maker.take_import()) {
    if (std::chrono::steady_clock::now() - waiting_since > std::chrono::duration<double>(2 * options.import_seconds + 5)) {
      maker.count_refusal("busy");
      co_return refusal(503, "this server is importing other models: try again in a moment", "Retry-After: 10\r\n");
    }
    asio::steady_timer pause(socket.get_executor(), std::chrono::milliseconds(100));
    co_await pause.async_wait(no_throw);
  }
  struct ImportDone {
    SessionMaker& maker;
    ~ImportDone() { maker.import_done(); }
  } import_done{maker};
  const ImportOutcome imported = co_await import_model(folder->path / "files", folder->path / "model.glb", options);
  if (!imported.error.empty()) {
    maker.count_refusal("import");
    log_info("upload-refused", {{"peer", address}, {"files", files.files()}, {"reason", imported.error}});
    co_return refusal(422, imported.error);
  }
  protocol::AssetAnnounce model;
  try {
    model = server.store().add_file(folder->path / "model.glb", protocol::AssetKind::Mesh, imported.name);
  } catch (const Error& e) {
    co_return refusal(500, std::string("the model could not be stored: ") + e.what());
  }
  if (scene) {
    if (const std::string why = maker.replace_model(*scene, model); !why.empty()) co_return refusal(409, why);
    server.relay().model_replaced(*scene);  // and the members on other instances
    co_return json_reply(200, {{"name", scene->name()}, {"page", "/scene/" + scene->name()}, {"triangles", imported.triangles}, {"bytes", model.size}});
  }
  const SessionMaker::Made made = maker.make_scene(model, address, SessionMaker::Clock::now());
  if (!made.session) co_return refusal(503, made.refusal);
  co_return json_reply(201, {{"name", made.session->name()}, {"page", "/scene/" + made.session->name()}, {"editor_key", made.key},
                             {"triangles", imported.triangles}, {"bytes", model.size}});
}

}  // namespace inkwire::server
