// inkwire-bench --suite rooms (SPEC N6-N8): sessions people make, measured against a real
// inkwire-server process on loopback as its users would feel them.
// - open: rooms opened per second by members joining with open_room (50 at a time, each opener
//   leaving once it holds its host key), and the time from join to host key;
// - first-face: "Start a call" (a member opens a room and sends its neutral photo, as the page
//   does) and a second member joining at once: from that join to the roster naming the first
//   (`roster_ms`), and to the first's neutral photo and landmarks on the second's disk, what its
//   grid draws the face from (`face_ms`); `start_to_face_ms` counts from the first's join;
// - upload: a 5 MB GLB (the milk truck with a 2048 x 2048 texture of photographic grain) posted
//   to /scenes, then a second member joining the new scene and drawing its first frame with the
//   native renderer here (`first_frame_ms` from the upload's first byte); replace: the same GLB
//   posted by the editor as a running scene's new model, four members in it, until every one
//   holds the new model and has drawn a frame of it (`every_member_ms`);
// - idle: the server's resident memory (/metrics process_resident_memory_bytes) with 1000 empty
//   rooms (each opened, then left: they wait room_idle_seconds) over the same after 1000 joins
//   of a configured session by the same openers (the reference: what the joins cost alone).
// Targets (issue 57): first face within 2 s, a 5 MB model on every member's screen within 3 s,
// 1000 idle rooms under 50 MB.
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <asio.hpp>
#include <asio/experimental/as_tuple.hpp>
#include <nlohmann/json.hpp>

#include "bench_harness.hpp"
#include "client/gl/canvas.hpp"
#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/model_bundle.hpp"
#include "net_load.hpp"
#include "protocol/framing.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;
using asio::ip::tcp;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
const fs::path kTruck = "/usr/share/assimp/models/glTF/CesiumMilkTruck";
const fs::path kPhoto = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// One HTTP exchange with the server under test: the whole answer.
std::string http(int port, const std::string& request) {
  asio::io_context io;
  tcp::socket s(io);
  s.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)});
  asio::write(s, asio::buffer(request));
  std::string answer;
  std::error_code ec;
  asio::read(s, asio::dynamic_buffer(answer), ec);
  return answer;
}

double rss_mb(int http_port) {
  const std::string metrics = http(http_port, "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n");
  const size_t at = metrics.find("\nprocess_resident_memory_bytes ");
  if (at == std::string::npos) throw Error("the server's /metrics has no process_resident_memory_bytes");
  return std::stod(metrics.substr(at + 31)) / (1 << 20);
}

// A model upload's answer body (JSON), or throws with the server's reason.
nlohmann::json post_model(int port, const std::string& target, const std::string& name, const std::string& bytes, const std::string& headers = "") {
  const std::string boundary = "----inkwire-bench-rooms";
  const std::string body = "--" + boundary + "\r\nContent-Disposition: form-data; name=\"files\"; filename=\"" + name +
                           "\"\r\nContent-Type: application/octet-stream\r\n\r\n" + bytes + "\r\n--" + boundary + "--\r\n";
  const std::string answer = http(port, "POST " + target + " HTTP/1.1\r\nHost: x\r\nContent-Type: multipart/form-data; boundary=" + boundary +
                                            "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n" + headers + "\r\n" + body);
  const size_t end = answer.find("\r\n\r\n");
  const nlohmann::json j = nlohmann::json::parse(end == std::string::npos ? "" : answer.substr(end + 4), nullptr, false);
  if (answer.rfind("HTTP/1.1 20", 0) != 0 || !j.is_object()) throw Error("the server refused the upload: " + answer.substr(0, 300));
  return j;
}

// The truck made one GLB of about 5 MB: its texture grown to 2048 x 2048 with grain, so it
// packs as a photograph does (a smooth texture would pack to a fraction).
std::string five_megabyte_glb(const fs::path& dir, uint32_t seed) {
  const fs::path folder = dir / ("truck-5mb-" + std::to_string(seed));
  fs::create_directories(folder);
  for (const char* f : {"CesiumMilkTruck.gltf", "CesiumMilkTruck.bin"}) fs::copy_file(kTruck / f, folder / f, fs::copy_options::overwrite_existing);
  Image texture = resized(load_image(kTruck / "CesiumMilkTruck.png"), 2048, 2048);
  for (int amplitude = 2;; amplitude += 2) {
    std::mt19937 rng(seed);
    Image grainy = texture;
    for (size_t i = 0; i < grainy.pixels.size(); ++i)
      if (i % 4 != 3) grainy.pixels[i] = uint8_t(std::clamp(int(texture.pixels[i]) + int(rng() % (2 * amplitude + 1)) - amplitude, 0, 255));
    const std::vector<uint8_t> png = encode_image(grainy, "png");
    std::ofstream(folder / "CesiumMilkTruck.png", std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    const std::optional<SelfContainedModel> glb = self_contained_model(folder / "CesiumMilkTruck.gltf");
    if (!glb) throw Error("the truck could not be made one GLB");
    if (glb->bytes.size() >= (5u << 20) || amplitude > 64) return std::string(glb->bytes.begin(), glb->bytes.end());
  }
}

// --- open: rooms opened per second ---------------------------------------------------------

struct Openers {
  tcp::endpoint server;
  int next = 0, total = 0, opened = 0, refused = 0;
  std::string prefix;
  bool open_room = true;
  std::vector<double> open_ms;
};

// Opens rooms one after another (prefix + index) until `total` are open: connect, hello, join
// with open_room, wait for the host key (or, joining an existing session, the snapshot), leave.
asio::awaitable<void> opener(Openers& o) {
  std::vector<uint8_t> chunk(16384);
  while (o.next < o.total) {
    const int index = o.next++;
    tcp::socket s(co_await asio::this_coro::executor);
    const auto start = Clock::now();
    if (auto [ec] = co_await s.async_connect(o.server, no_throw); ec) {
      ++o.refused;
      continue;
    }
    s.set_option(tcp::no_delay(true));
    const protocol::Bytes hello = protocol::encode(protocol::Hello{.client_name = "opener"});
    const protocol::Bytes join = protocol::encode(protocol::Join{.session = o.open_room ? o.prefix + std::to_string(index) : o.prefix, .token = "", .open_room = o.open_room});
    co_await asio::async_write(s, asio::buffer(hello), no_throw);
    co_await asio::async_write(s, asio::buffer(join), no_throw);
    protocol::FrameDecoder frames;
    bool done = false, failed = false;
    while (!done && !failed) {
      auto [ec, n] = co_await s.async_read_some(asio::buffer(chunk), no_throw);
      if (ec) break;
      frames.feed(chunk.data(), n);
      while (const auto m = frames.next()) {
        if (std::holds_alternative<protocol::ErrorMessage>(*m)) failed = true;
        if (o.open_room ? std::holds_alternative<protocol::HostKey>(*m) : std::holds_alternative<protocol::Snapshot>(*m)) done = true;
      }
    }
    if (done) ++o.opened, o.open_ms.push_back(ms_since(start));
    else ++o.refused;
  }
}

Openers open_many(int port, const std::string& prefix, int total, bool open_room, double* seconds) {
  Openers o{.server = {asio::ip::make_address("127.0.0.1"), uint16_t(port)}, .total = total, .prefix = prefix, .open_room = open_room};
  asio::io_context io(1);
  for (int i = 0; i < 50; ++i) asio::co_spawn(io, opener(o), asio::detached);
  const auto start = Clock::now();
  io.run();
  *seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return o;
}

// Waits until the server has no client connected (the openers' sockets closed) and two of its
// once-a-second rounds (which hand freed memory back) have passed.
void settle(int http_port) {
  for (int i = 0; i < 100; ++i) {
    const std::string metrics = http(http_port, "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n");
    if (metrics.find("\ninkwire_connections 0\n") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
}

// --- first-face: from Start a call to the second member seeing the first ----------------------

struct FaceTimes {
  std::vector<double> roster_ms, face_ms, start_to_face_ms;
};

void first_faces(const std::string& address, const fs::path& dir, int trials, FaceTimes& t) {
  const Image photo = load_image(kPhoto);
  const protocol::Bytes jpeg = encode_image(photo, "jpg", 90);
  for (int k = 0; k < trials; ++k) {
    const std::string room = "call-" + std::to_string(k);
    SessionClient first(address, "First"), second(address, "Second");
    const auto start = Clock::now();
    first.join(room, "", true);
    first.send(protocol::NeutralPhoto{.jpeg = jpeg});
    const auto joined = Clock::now();
    second.join(room, "");
    const protocol::CallMember* seen = nullptr;
    bool rostered = false;
    while (ms_since(joined) < 20000) {
      const protocol::Roster roster = second.roster();
      seen = nullptr;
      for (const auto& m : roster.members)
        if (m.name == "First") seen = &m;
      if (seen && !rostered) t.roster_ms.push_back(ms_since(joined)), rostered = true;
      if (seen && seen->assets.size() == 2) {
        AssetCache cache(dir / ("cache-" + std::to_string(k)));
        for (const auto& a : seen->assets) second.fetch_asset(a, cache);
        t.face_ms.push_back(ms_since(joined));
        t.start_to_face_ms.push_back(ms_since(start));
        break;
      }
      second.wait_for_update(second.updates(), std::chrono::milliseconds(50));
    }
  }
}

// --- upload: a 5 MB model to the first frame at a second member ---------------------------------

// Draws the member's current scene once, finished: its first frame (kept as `picture`).
Image draw_frame(SessionClient& member, AssetCache& cache, Canvas& canvas) {
  const protocol::Snapshot state = member.state();
  SessionView view;
  view.update(state, member.fetch_assets(state, cache));
  if (!view.content_error().empty()) throw Error("the member cannot show the uploaded model: " + view.content_error());
  canvas.bind();
  view.draw(canvas.size(), 0.0, 0);
  return canvas.read();  // the frame finished and read back, as a window's swap would wait for it
}

}  // namespace

std::vector<Result> run_rooms_suite(Harness& harness) {
  const fs::path dir = fs::path(harness.options().output_dir.empty() ? "." : harness.options().output_dir) / "rooms-bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string server_bin = program_beside_bench("inkwire-server");
  const int port = free_loopback_port(), http_port = free_loopback_port();
  // Rooms wait ten minutes empty (the idle row counts them all); the caps leave room for the run.
  std::ofstream(dir / "server.json") << nlohmann::json{
      {"http", "127.0.0.1:" + std::to_string(http_port)},
      {"sessions", {{{"name", "lobby"}, {"kind", "conference"}}}},
      {"making", {{"room_idle_seconds", 600}, {"max_rooms", 10000}, {"max_scenes", 100}, {"uploads_per_minute_per_address", 1000}}}}.dump();
  const pid_t server = spawn_process({server_bin, "--listen", "127.0.0.1:" + std::to_string(port), "--config", (dir / "server.json").string(), "--data",
                                      (dir / "data").string(), "--quiet"},
                                     (dir / "server.log").string());
  struct Stop {
    pid_t pid;
    ~Stop() {
      kill(pid, SIGTERM);
      waitpid(pid, nullptr, 0);
    }
  } stop{server};
  for (int i = 0; i < 200 && !(port_answers(port) && port_answers(http_port)); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::string address = "127.0.0.1:" + std::to_string(port);
  std::vector<Result> results;

  // idle's reference, then open: 1000 joins of a configured session, 1000 rooms opened.
  double seconds = 0, join_seconds = 0;
  settle(http_port);
  const double rss_start = rss_mb(http_port);
  const Openers joins = open_many(port, "lobby", 1000, false, &join_seconds);
  settle(http_port);
  const double rss_joined = rss_mb(http_port);
  const Openers rooms = open_many(port, "room-", 1000, true, &seconds);
  Result open{.suite = "rooms", .renderer = "rooms", .variant = "open,rooms=1000,at_once=50", .object = "-"};
  open.counters = {{"rooms_per_second", rooms.opened / seconds}, {"rooms_opened", double(rooms.opened)}, {"refused", double(rooms.refused)},
                   {"open_ms_p50", percentile(rooms.open_ms, 0.5)}, {"open_ms_p99", percentile(rooms.open_ms, 0.99)},
                   {"joins_per_second_reference", joins.opened / std::max(1e-9, join_seconds)}};
  settle(http_port);
  const double rss_rooms = rss_mb(http_port);
  const std::string metrics = http(http_port, "GET /metrics HTTP/1.1\r\nHost: x\r\n\r\n");
  const size_t open_at = metrics.find("\ninkwire_rooms_open ");
  const double rooms_open = open_at == std::string::npos ? -1 : std::stod(metrics.substr(open_at + 20));
  Result idle{.suite = "rooms", .renderer = "rooms", .variant = "idle,rooms=1000", .object = "-"};
  idle.counters = {{"rooms_open", rooms_open}, {"rss_mb_start", rss_start}, {"rss_mb_after_joins", rss_joined}, {"rss_mb_after_rooms", rss_rooms},
                   {"rss_mb_rooms", rss_rooms - rss_joined}, {"kb_per_room", (rss_rooms - rss_joined) * 1024 / std::max(1, rooms.opened)}};

  // first-face.
  FaceTimes faces;
  first_faces(address, dir, 50, faces);
  Result face{.suite = "rooms", .renderer = "rooms", .variant = "first-face,trials=" + std::to_string(faces.face_ms.size()), .object = "-"};
  // The server's first photo of all also loads the analyst's face model: its own figure.
  const std::vector<double> warm(faces.face_ms.begin() + std::min<size_t>(1, faces.face_ms.size()), faces.face_ms.end());
  face.counters = {{"face_ms_first_of_server", faces.face_ms.empty() ? 0 : faces.face_ms.front()}, {"face_ms_p99_after_first", percentile(warm, 0.99)},
                   {"roster_ms_p50", percentile(faces.roster_ms, 0.5)},       {"roster_ms_p99", percentile(faces.roster_ms, 0.99)},
                   {"face_ms_p50", percentile(faces.face_ms, 0.5)},           {"face_ms_p99", percentile(faces.face_ms, 0.99)},
                   {"start_to_face_ms_p50", percentile(faces.start_to_face_ms, 0.5)}, {"start_to_face_ms_p99", percentile(faces.start_to_face_ms, 0.99)}};

  // upload and replace, five times each.
  const std::string glb = five_megabyte_glb(dir, 57), other_glb = five_megabyte_glb(dir, 58);
  Canvas canvas(640, 480, 1);
  std::vector<double> upload_ms, first_frame_ms, every_member_ms;
  std::string scene, key;
  for (int k = 0; k < 5; ++k) {
    const auto start = Clock::now();
    const nlohmann::json made = post_model(http_port, "/scenes", "truck-5mb.glb", glb);
    upload_ms.push_back(ms_since(start));
    scene = made.at("name").get<std::string>(), key = made.at("editor_key").get<std::string>();
    SessionClient member(address, "member");
    member.join(scene, "");
    AssetCache cache(dir / ("cache-upload-" + std::to_string(k)));
    const Image picture = draw_frame(member, cache, canvas);
    first_frame_ms.push_back(ms_since(start));
    if (k == 0) save_image(picture, dir / "upload-first-frame.png");
  }
  // The last scene, four members in it; each replace brings the truck under the other texture's
  // grain (a model they do not hold: each round's caches are new).
  std::vector<std::unique_ptr<SessionClient>> members;
  for (int i = 0; i < 4; ++i) {
    members.push_back(std::make_unique<SessionClient>(address, "member-" + std::to_string(i)));
    members.back()->join(scene, "");
  }
  for (int k = 0; k < 5; ++k) {
    const std::string& model = k % 2 == 0 ? other_glb : glb;
    std::vector<protocol::Snapshot> before;
    for (auto& m : members) before.push_back(m->state());
    const auto start = Clock::now();
    post_model(http_port, "/scenes/" + scene + "/model", "truck-5mb.glb", model, "X-Inkwire-Editor-Key: " + key + "\r\n");
    double slowest = 0;
    std::vector<std::thread> fetchers;
    std::vector<double> fetched(members.size());
    for (size_t i = 0; i < members.size(); ++i)
      fetchers.emplace_back([&, i] {
        while (members[i]->state().assets == before[i].assets) members[i]->wait_for_update(members[i]->updates(), std::chrono::milliseconds(50));
        AssetCache cache(dir / ("cache-replace-" + std::to_string(k) + "-" + std::to_string(i)));
        members[i]->fetch_assets(members[i]->state(), cache);
        fetched[i] = ms_since(start);
      });
    for (auto& t : fetchers) t.join();
    // Each member draws on its own machine: the drawing's cost once, after the last one's fetch.
    AssetCache cache(dir / ("cache-replace-" + std::to_string(k) + "-0"));
    const auto draw_start = Clock::now();
    draw_frame(*members[0], cache, canvas);
    for (const double f : fetched) slowest = std::max(slowest, f);
    every_member_ms.push_back(slowest + ms_since(draw_start));
  }
  Result upload{.suite = "rooms", .renderer = "rooms", .variant = "upload,glb=5MB", .object = "milk-truck", .frames = 5};
  upload.counters = {{"glb_bytes", double(glb.size())}, {"upload_ms_median", percentile(upload_ms, 0.5)},
                     {"first_frame_ms_median", percentile(first_frame_ms, 0.5)}, {"first_frame_ms_max", percentile(first_frame_ms, 1.0)}};
  Result replace{.suite = "rooms", .renderer = "rooms", .variant = "replace,glb=5MB,members=4", .object = "milk-truck", .frames = 5};
  replace.counters = {{"glb_bytes", double(glb.size())}, {"every_member_ms_median", percentile(every_member_ms, 0.5)},
                      {"every_member_ms_max", percentile(every_member_ms, 1.0)}};
  return {open, face, upload, replace, idle};
}

}  // namespace inkwire::bench
