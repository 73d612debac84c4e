// --suite net: the load test (SPEC N1-N4). A real server (the inkwire_server library on its own
// I/O thread) and N simulated clients (coroutines on a second thread) in M sessions on
// loopback; in each session one client moves the camera at R Hz and every other member
// receives it. Measures delivered messages per second, delivery latency, bytes per message and
// stalls; then the bytes a turntable interaction costs after the first download, and the
// machine's own pauses, which set a floor under the latency tail.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include <asio.hpp>
#include <asio/experimental/as_tuple.hpp>

#include "bench_harness.hpp"
#include "client/net/session_client.hpp"
#include "protocol/framing.hpp"
#include "server/server.hpp"

namespace inkwire::bench {
namespace {

using namespace protocol;
using Clock = std::chrono::steady_clock;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

struct LoadShape {
  int clients, sessions, hz;
  double seconds;
};

// Everything the simulated clients share; touched only on the clients' I/O thread.
struct Load {
  LoadShape shape;
  std::vector<std::vector<Clock::time_point>> sent;  // [session][sequence]
  std::vector<double> latencies_ms;
  int64_t stalls = 0, delivered = 0, joined = 0, failed = 0;
  Clock::time_point start, stop;
};

// Takes the frame already encoded: GCC 12 mishandles temporaries (a Message built in the
// argument list) that live across a co_await.
asio::awaitable<void> write_frame(asio::ip::tcp::socket& s, const Bytes& frame) {
  co_await asio::async_write(s, asio::buffer(frame), no_throw);
}

// Reads whatever has arrived in one receive and splits it into messages, as the server and
// the real client do: a simulated client should cost what a real one costs.
class MessageReader {
 public:
  explicit MessageReader(asio::ip::tcp::socket& socket) : socket_(socket), chunk_(4096) {}
  asio::awaitable<std::optional<Message>> next() {
    for (;;) {
      if (std::optional<Message> m = frames_.next()) co_return m;
      auto [ec, n] = co_await socket_.async_read_some(asio::buffer(chunk_), no_throw);
      if (ec) co_return std::nullopt;
      frames_.feed(chunk_.data(), n);
    }
  }

 private:
  asio::ip::tcp::socket& socket_;
  std::vector<uint8_t> chunk_;
  FrameDecoder frames_;
};

// One simulated client: joins its session; the session's first client sends poses at R Hz,
// the others time each pose's delivery and count gaps over three periods as stalls.
asio::awaitable<void> simulated_client(asio::ip::tcp::endpoint server, Load& load, int index) {
  const int session = index % load.shape.sessions;
  const bool sender = index < load.shape.sessions;
  asio::ip::tcp::socket s(co_await asio::this_coro::executor);
  auto [ec] = co_await s.async_connect(server, no_throw);
  if (ec) {
    ++load.failed;
    co_return;
  }
  s.set_option(asio::ip::tcp::no_delay(true));
  MessageReader reader(s);
  const Bytes hello = encode(Hello{.client_name = "load-" + std::to_string(index)});
  const Bytes join = encode(Join{.session = "s" + std::to_string(session), .token = ""});
  co_await write_frame(s, hello);
  co_await write_frame(s, join);
  for (int got = 0; got < 2;) {  // welcome, snapshot
    auto m = co_await reader.next();
    if (!m || std::holds_alternative<ErrorMessage>(*m)) {
      ++load.failed;
      co_return;
    }
    ++got;
  }
  ++load.joined;
  if (sender) {
    asio::steady_timer timer(s.get_executor());
    // Wait until everyone has joined, then send for the measured time.
    while (load.joined + load.failed < load.shape.clients) {
      timer.expires_after(std::chrono::milliseconds(5));
      co_await timer.async_wait(no_throw);
    }
    const auto period = std::chrono::microseconds(1000000 / load.shape.hz);
    // Senders are spread over the period as independent clients would be, not phase-locked.
    auto next = Clock::now() + period * session / load.shape.sessions;
    for (uint32_t seq = 0; seq < load.sent[size_t(session)].size(); ++seq) {
      next += period;
      timer.expires_at(next);
      co_await timer.async_wait(no_throw);
      CameraPose pose{.sequence = seq, .position = {0, 1, 10}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fov_y_degrees = 45};
      const Bytes frame = encode(pose);
      load.sent[size_t(session)][seq] = Clock::now();
      co_await write_frame(s, frame);
    }
    co_return;
  }
  Clock::time_point last{};
  const auto stall = std::chrono::microseconds(3 * 1000000 / load.shape.hz);
  for (;;) {
    auto m = co_await reader.next();
    if (!m) co_return;
    const auto* pose = std::get_if<CameraPose>(&*m);
    if (!pose) continue;
    const auto now = Clock::now();
    load.latencies_ms.push_back(std::chrono::duration<double, std::milli>(now - load.sent[size_t(session)][pose->sequence]).count());
    ++load.delivered;
    if (last != Clock::time_point{} && now - last > stall) ++load.stalls;
    last = now;
    if (pose->sequence + 1 == load.sent[size_t(session)].size()) co_return;
  }
}

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * double(v.size())))];
}

server::ServerConfig load_server_config(const std::string& data_dir, int sessions) {
  server::ServerConfig config;
  config.port = 0;
  config.data_dir = data_dir;
  for (int i = 0; i < sessions; ++i) {
    server::SessionConfig session;
    session.name = "s" + std::to_string(i);
    config.sessions.push_back(std::move(session));
  }
  return config;
}

Result run_load(const LoadShape& shape, const std::string& data_dir) {
  asio::io_context server_io(1);
  server::Server server(server_io, load_server_config(data_dir, shape.sessions));
  server.start();
  double server_cpu_seconds = 0;
  std::thread server_thread([&] {
    server_io.run();
    server_cpu_seconds = thread_cpu_seconds();
  });

  Load load;
  load.shape = shape;
  load.sent.assign(size_t(shape.sessions), std::vector<Clock::time_point>(size_t(shape.seconds * shape.hz)));
  asio::io_context client_io(1);
  const asio::ip::tcp::endpoint endpoint{asio::ip::make_address("127.0.0.1"), server.port()};
  for (int i = 0; i < shape.clients; ++i) asio::co_spawn(client_io, simulated_client(endpoint, load, i), asio::detached);
  const auto start = Clock::now();
  const double clients_cpu0 = thread_cpu_seconds();
  client_io.run();
  const double clients_cpu_seconds = thread_cpu_seconds() - clients_cpu0;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  asio::post(server_io, [&] { server.stop(); });
  server_thread.join();

  Result r;
  r.suite = "net", r.renderer = "net", r.object = "-";
  r.variant = "clients=" + std::to_string(shape.clients) + ",sessions=" + std::to_string(shape.sessions) + ",hz=" + std::to_string(shape.hz);
  const double expected = double(shape.clients - shape.sessions) * double(load.sent[0].size());
  r.counters = {{"clients", shape.clients}, {"sessions", shape.sessions}, {"joined", double(load.joined)},
                {"msgs_per_second", double(load.delivered) / seconds}, {"delivered_fraction", double(load.delivered) / expected},
                {"p50_ms", percentile(load.latencies_ms, 0.50)}, {"p99_ms", percentile(load.latencies_ms, 0.99)},
                {"max_ms", percentile(load.latencies_ms, 1.0)}, {"stalls", double(load.stalls)},
                {"bytes_per_message", double(encoded_size(CameraPose{}))},
                // Each side's CPU time over the run as a share of one core (joins included):
                // how busy server and clients really are, which p99 alone does not tell.
                {"server_cpu_fraction", server_cpu_seconds / seconds}, {"clients_cpu_fraction", clients_cpu_seconds / seconds}};
  return r;
}

// After a turntable session's assets are downloaded, one interaction (the viewer turns the
// object: one pose to the session) costs what crosses the wire for it.
Result turntable_interaction(const std::string& data_dir) {
  asio::io_context server_io(1);
  server::ServerConfig config = server::ServerConfig::embedded_default();
  config.port = 0;
  config.data_dir = data_dir;
  server::Server server(server_io, config);
  server.start();
  std::thread server_thread([&] { server_io.run(); });
  Result r;
  r.suite = "net", r.renderer = "net", r.variant = "turntable-interaction", r.object = "-";
  {
    const std::string address = "127.0.0.1:" + std::to_string(server.port());
    SessionClient viewer(address, "viewer"), other(address, "other");
    const Snapshot state = viewer.join("turntable", "");
    other.join("turntable", "");
    AssetCache cache(data_dir + "-cache");
    viewer.fetch_assets(state, cache);
    const uint64_t download = viewer.bytes_received();
    const uint64_t sent0 = viewer.bytes_sent(), received0 = viewer.bytes_received();
    const int interactions = 100;
    for (int i = 1; i <= interactions; ++i) viewer.send(ObjectPose{.sequence = uint32_t(i), .rotation = {0, std::sin(i * 0.01f), 0, std::cos(i * 0.01f)}, .translation = {}, .scale = 1});
    // Poses are state: a burst may be coalesced on the way (latest wins), so wait for the last.
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (other.state().object.sequence != uint32_t(interactions) && other.connected() && Clock::now() < deadline)
      other.wait_for_update(other.updates(), std::chrono::milliseconds(100));
    const double per = double(viewer.bytes_sent() - sent0 + viewer.bytes_received() - received0) / interactions;
    r.counters = {{"bytes_per_interaction", per}, {"download_bytes", double(download)},
                  {"assets", double(state.assets.size())}};
  }
  asio::post(server_io, [&] { server.stop(); });
  server_thread.join();
  return r;
}

// The machine's own pauses: two threads (one per core, as the server and the clients use)
// spin reading the clock; every gap over half a millisecond is time neither could have served
// in. On a shared virtual machine they alone can be as long as the latency target.
constexpr double kPauseMs = 0.5;

Result machine_pauses(double seconds) {
  std::vector<double> gaps[2];
  auto spin = [&](std::vector<double>& out) {
    const auto start = Clock::now();
    auto last = start;
    while (last - start < std::chrono::duration<double>(seconds)) {
      const auto now = Clock::now();
      const double gap = std::chrono::duration<double, std::milli>(now - last).count();
      if (gap > kPauseMs) out.push_back(gap);
      last = now;
    }
  };
  std::thread other([&] { spin(gaps[1]); });
  spin(gaps[0]);
  other.join();
  std::vector<double> all = gaps[0];
  all.insert(all.end(), gaps[1].begin(), gaps[1].end());
  double paused = 0;
  for (const double g : all) paused += g;
  Result r;
  r.suite = "net", r.renderer = "net", r.variant = "machine-pauses", r.object = "-";
  r.counters = {{"pauses", double(all.size())}, {"pause_max_ms", percentile(all, 1.0)},
                {"paused_fraction", paused / (2 * seconds * 1000)}};
  return r;
}

}  // namespace

std::vector<Result> run_net_suite(Harness& harness) {
  // 1000 clients and the server's 1000 sockets in one process need more than 1024 descriptors.
  rlimit limit{};
  getrlimit(RLIMIT_NOFILE, &limit);
  limit.rlim_cur = std::min<rlim_t>(limit.rlim_max, 8192);
  setrlimit(RLIMIT_NOFILE, &limit);
  const std::string base = (harness.options().output_dir.empty() ? std::string(".") : harness.options().output_dir) + "/net-bench-data";
  std::filesystem::remove_all(base);
  std::vector<Result> results;
  int run = 0;
  for (LoadShape shape : {LoadShape{100, 10, 30, 5}, LoadShape{1000, 100, 30, 5}}) {
    results.push_back(run_load(shape, base + "/load-" + std::to_string(run++)));
    const auto& c = results.back().counters;
    std::fprintf(stderr, "  net %s: %.0f msgs/s, p50 %.2f ms, p99 %.2f ms, stalls %.0f, delivered %.3f\n", results.back().variant.c_str(),
                 c.at("msgs_per_second"), c.at("p50_ms"), c.at("p99_ms"), c.at("stalls"), c.at("delivered_fraction"));
  }
  results.push_back(turntable_interaction(base + "/turntable"));
  results.push_back(machine_pauses(5));
  const auto& pauses = results.back().counters;
  std::fprintf(stderr, "  net machine pauses: %.0f over %.1f ms, longest %.2f ms, %.2f%% of the time\n", pauses.at("pauses"), kPauseMs,
               pauses.at("pause_max_ms"), 100 * pauses.at("paused_fraction"));
  return results;
}

}  // namespace inkwire::bench
