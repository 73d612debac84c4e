// inkwire-bench --suite abuse (SPEC D6): a real inkwire-server process on loopback serving 1000
// legitimate clients at 30 Hz on 100 sessions (the net suite's simulated clients) while hostile
// connections arrive all the time: garbage bytes, truncated and oversized frames, slow-loris HTTP
// heads, WebSocket floods of pings and one-byte fragments, joins with wrong tokens and visitors
// presenting on a product. Reports the legitimate clients' p99 and delivered fraction, the
// hostile connections the server ended, and the server's RSS and open descriptors before, during
// and after (from /proc: the server is a process of its own).
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include <asio.hpp>
#include <asio/experimental/as_tuple.hpp>
#include <nlohmann/json.hpp>

#include "bench_harness.hpp"
#include "common/error.hpp"
#include "net_load.hpp"
#include "protocol/framing.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;
using namespace protocol;
using asio::ip::tcp;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

struct Hostile {
  tcp::endpoint native, http;
  Clock::time_point until;
  uint64_t attempts = 0, ended_by_server = 0;
};

Bytes frame_of(const Message& m) { return encode(m); }

std::string ws_upgrade(int port) {
  return "GET /ws HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
         "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n";
}

// A masked WebSocket frame (mask 0: the bytes as they are).
std::string ws_frame(uint8_t first, const std::string& payload) {
  std::string f{char(first), char(0x80 | payload.size())};
  f += std::string(4, '\0');
  return f + payload;
}

// Reads until the server closes (or `patience` passes); true when the server ended it.
asio::awaitable<bool> server_ends(tcp::socket& s, std::chrono::milliseconds patience) {
  asio::steady_timer timer(s.get_executor(), patience);
  timer.async_wait([&](std::error_code ec) {
    if (!ec) s.close();
  });
  char buffer[4096];
  for (;;) {
    auto [ec, n] = co_await s.async_read_some(asio::buffer(buffer), no_throw);
    if (ec) {
      timer.cancel();
      co_return ec == asio::error::eof || ec == asio::error::connection_reset;
    }
  }
}

// One attacker: connection after connection of kind `kind`, until the run ends.
asio::awaitable<void> attacker(Hostile& h, int kind, uint32_t seed) {
  std::mt19937 rng(seed);
  while (Clock::now() < h.until) {
    tcp::socket s(co_await asio::this_coro::executor);
    const bool web = kind == 3 || kind == 4 || kind == 5;
    auto [ec] = co_await s.async_connect(web ? h.http : h.native, no_throw);
    if (ec) continue;
    ++h.attempts;
    std::string out;
    switch (kind) {
      case 0: {  // garbage
        for (int i = 0; i < 64; ++i) out += char(rng());
        break;
      }
      case 1: {  // a frame that says more than comes, then silence
        const Bytes hello = frame_of(Hello{.client_name = "truncated"});
        out.assign(hello.begin(), hello.begin() + 5);
        break;
      }
      case 2: {  // a frame header over the limit
        out = std::string("\xff\xff\xff\x7f\x01\x00", 6);
        break;
      }
      case 3: {  // slow loris: a head that never ends
        out = "GET / HTTP/1.1\r\nHost: x\r\nX-Slow: ";
        break;
      }
      case 4: {  // a WebSocket flooded with pings
        out = ws_upgrade(h.http.port());
        for (int i = 0; i < 500; ++i) out += ws_frame(0x89, "ping");
        break;
      }
      case 5: {  // a WebSocket message in one-byte fragments without end
        out = ws_upgrade(h.http.port()) + ws_frame(0x02, "\x01");
        for (int i = 0; i < 2000; ++i) out += ws_frame(0x00, "\x01");
        break;
      }
      case 6: {  // guessing a session's token
        const Bytes hello = frame_of(Hello{.client_name = "guesser"});
        out.assign(hello.begin(), hello.end());
        for (int i = 0; i < 5; ++i) {
          const Bytes join = frame_of(Join{.session = "locked", .token = "guess-" + std::to_string(rng())});
          out.append(join.begin(), join.end());
        }
        break;
      }
      default: {  // a visitor presenting on a product and restyling it
        const Bytes hello = frame_of(Hello{.client_name = "stranger"}), join = frame_of(Join{.session = "product", .token = ""});
        out.append(hello.begin(), hello.end());
        out.append(join.begin(), join.end());
        for (uint32_t i = 1; i <= 50; ++i) {
          const Bytes pose = frame_of(ObjectPose{.sequence = i, .rotation = {0, 0, 0, 1}, .translation = {}, .scale = 1});
          out.append(pose.begin(), pose.end());
        }
        const Bytes style = frame_of(StyleChange{.renderer = "comic", .settings = {}});
        out.append(style.begin(), style.end());
        break;
      }
    }
    co_await asio::async_write(s, asio::buffer(out), no_throw);
    // The attacker holds the connection as long as the server lets it (at most 8 s).
    if (co_await server_ends(s, std::chrono::milliseconds(8000))) ++h.ended_by_server;
  }
}

}  // namespace

std::vector<Result> run_abuse_suite(Harness& harness) {
  const fs::path dir = fs::path(harness.options().output_dir.empty() ? "." : harness.options().output_dir) / "abuse-bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string bin = std::filesystem::path(program_beside_bench("inkwire-server")).parent_path().string();
  const fs::path duck = "/usr/share/assimp/models/Collada/duck.dae";
  if (std::system(("'" + bin + "/inkwire-server' add-product product --mesh '" + duck.string() + "' --samples 12 --size 128 --editor-token owner --data '" +
                   (dir / "data").string() + "' > '" + (dir / "add.log").string() + "'").c_str()) != 0)
    throw Error("the abuse suite could not put its product on the server (see " + (dir / "add.log").string() + ")");
  const LoadShape shape{.clients = 1000, .sessions = 100, .hz = 30, .seconds = 8};
  nlohmann::json sessions = nlohmann::json::array({{{"name", "locked"}, {"kind", "scene"}, {"token", "s3cret"}}});
  for (int i = 0; i < shape.sessions; ++i) sessions.push_back({{"name", "s" + std::to_string(i)}, {"kind", "scene"}});
  const int port = free_loopback_port(), http_port = free_loopback_port();
  std::ofstream(dir / "server.json") << nlohmann::json{{"http", "127.0.0.1:" + std::to_string(http_port)}, {"sessions", sessions},
                                                       {"http_head_timeout_seconds", 2}}.dump();
  const pid_t server = fork();
  if (server == 0) {
    const std::string listen = "127.0.0.1:" + std::to_string(port), config = (dir / "server.json").string(), data = (dir / "data").string();
    freopen((dir / "server.log").c_str(), "w", stderr);
    execl((bin + "/inkwire-server").c_str(), "inkwire-server", "--listen", listen.c_str(), "--config", config.c_str(), "--data", data.c_str(), "--quiet",
          nullptr);
    _exit(127);
  }
  // Serving once the native port answers.
  for (int i = 0; i < 200 && !port_answers(port); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const double rss_before = process_rss_mb(server), fds_before = process_open_fds(server);

  Load load(shape, 1);
  const tcp::endpoint native{asio::ip::make_address("127.0.0.1"), uint16_t(port)}, http{asio::ip::make_address("127.0.0.1"), uint16_t(http_port)};
  Hostile hostile{.native = native, .http = http, .until = Clock::now() + std::chrono::milliseconds(int64_t(shape.seconds * 1000) + 3000)};
  asio::io_context hostile_io(1), client_io(1);
  for (int i = 0; i < 8 * 25; ++i) asio::co_spawn(hostile_io, attacker(hostile, i % 8, uint32_t(i)), asio::detached);
  double rss_during = 0, fds_during = 0;
  std::thread attackers([&] { hostile_io.run(); });
  std::thread sampler([&] {
    std::this_thread::sleep_for(std::chrono::seconds(6));
    rss_during = process_rss_mb(server), fds_during = process_open_fds(server);
  });
  for (int i = 0; i < shape.clients; ++i) asio::co_spawn(client_io, simulated_client({native}, load, i), asio::detached);
  client_io.run();
  sampler.join();
  attackers.join();
  std::this_thread::sleep_for(std::chrono::seconds(3));  // the last hostile connections' deadlines pass
  const double rss_after = process_rss_mb(server), fds_after = process_open_fds(server);
  kill(server, SIGTERM);
  waitpid(server, nullptr, 0);

  Result r{.suite = "abuse", .renderer = "abuse", .variant = "legit=" + std::to_string(shape.clients) + ",hostile=" + std::to_string(hostile.attempts),
           .object = "-"};
  r.counters = {{"p99_ms", percentile(load.latencies_ms[0], 0.99)}, {"delivered_fraction", double(load.delivered) / load.expected()},
                {"stalls", double(load.stalls)}, {"hostile_refused", double(hostile.ended_by_server)}, {"hostile_connections", double(hostile.attempts)},
                {"rss_mb_before", rss_before}, {"rss_mb_during", rss_during}, {"rss_mb_after", rss_after},
                {"fds_before", fds_before}, {"fds_during", fds_during}, {"fds_after", fds_after}};
  return {r};
}

}  // namespace inkwire::bench
