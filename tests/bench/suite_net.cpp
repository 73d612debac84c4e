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
#include "net_load.hpp"
#include "client/net/session_client.hpp"
#include "protocol/framing.hpp"
#include "server/server.hpp"

namespace inkwire::bench {

// Two instances on one broker, and the brokers alone (suite_net_instances.cpp).
std::vector<Result> run_net_instance_rows(const std::string& data_dir);

namespace {

using namespace protocol;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

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

  Load load(shape, 1);
  asio::io_context client_io(1);
  const asio::ip::tcp::endpoint endpoint{asio::ip::make_address("127.0.0.1"), server.port()};
  for (int i = 0; i < shape.clients; ++i) asio::co_spawn(client_io, simulated_client({endpoint}, load, i), asio::detached);
  const auto start = Clock::now();
  const double clients_cpu0 = thread_cpu_seconds();
  client_io.run();
  const double clients_cpu_seconds = thread_cpu_seconds() - clients_cpu0;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  asio::post(server_io, [&] { server.stop(); });
  server_thread.join();

  Result r;
  r.suite = "net", r.renderer = "net", r.object = "-";
  r.variant = shape.variant();
  const double expected = load.expected();
  r.counters = {{"clients", shape.clients}, {"sessions", shape.sessions}, {"joined", double(load.joined)},
                {"msgs_per_second", double(load.delivered) / seconds}, {"delivered_fraction", double(load.delivered) / expected},
                {"p50_ms", percentile(load.latencies_ms[0], 0.50)}, {"p99_ms", percentile(load.latencies_ms[0], 0.99)},
                {"max_ms", percentile(load.latencies_ms[0], 1.0)}, {"stalls", double(load.stalls)},
                {"bytes_per_message", double(encoded_size(CameraPose{}))},
                // Each side's CPU time over the run as a share of one core (joins included):
                // how busy server and clients really are, which p99 alone does not tell.
                {"server_cpu_fraction", server_cpu_seconds / seconds}, {"clients_cpu_fraction", clients_cpu_seconds / seconds}};
  return r;
}

// After a turntable session's assets are downloaded, one interaction costs what crosses the wire
// for it: an editor turning the product for everyone (one pose to the session), and a visitor
// turning its own view (nothing: the view is the visitor's own, SPEC T13). A visitor's pose to the
// session is refused (it may not change what others see), so it is not what is measured.
std::vector<Result> turntable_interaction(const std::string& data_dir) {
  constexpr const char* kEditorToken = "bench-editor";
  asio::io_context server_io(1);
  server::ServerConfig config = server::ServerConfig::embedded_default();
  config.port = 0;
  config.data_dir = data_dir;
  for (server::SessionConfig& s : config.sessions)
    if (s.name == "turntable") s.editor_token = kEditorToken;
  server::Server server(server_io, config);
  server.start();
  std::thread server_thread([&] { server_io.run(); });
  Result r, own;
  r.suite = "net", r.renderer = "net", r.variant = "turntable-interaction", r.object = "-";
  own.suite = "net", own.renderer = "net", own.variant = "turntable-visitor-view", own.object = "-";
  {
    const std::string address = "127.0.0.1:" + std::to_string(server.port());
    SessionClient viewer(address, "editor"), other(address, "visitor");
    const Snapshot state = viewer.join("turntable", kEditorToken);
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
                  {"assets", double(state.assets.size())}, {"refused", double(viewer.refusals())}};
    // The visitor turns its own view as often: its client draws it and sends nothing.
    const uint64_t visitor0 = other.bytes_sent() + other.bytes_received();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    own.counters = {{"bytes_per_interaction", double(other.bytes_sent() + other.bytes_received() - visitor0) / interactions},
                    {"refused", double(other.refusals())}};
  }
  asio::post(server_io, [&] { server.stop(); });
  server_thread.join();
  return {r, own};
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
  for (Result& r : run_net_instance_rows(base)) results.push_back(std::move(r));
  for (Result& r : turntable_interaction(base + "/turntable")) results.push_back(std::move(r));
  results.push_back(machine_pauses(5));
  const auto& pauses = results.back().counters;
  std::fprintf(stderr, "  net machine pauses: %.0f over %.1f ms, longest %.2f ms, %.2f%% of the time\n", pauses.at("pauses"), kPauseMs,
               pauses.at("pause_max_ms"), 100 * pauses.at("paused_fraction"));
  return results;
}

}  // namespace inkwire::bench
