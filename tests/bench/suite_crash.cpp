// inkwire-bench --suite crash (SPEC D3, D6): kill -9 at random moments, a hundred times, then
// count what was lost. Half the kills hit `inkwire-server add-product` putting a small product on
// the server; the other half hit a running server while a member changes its session's style and
// camera many times a second. After every kill the server starts again on the same data; at the
// end every product add-product said it stored must be served whole (each asset fetched and
// checked against its hash by the client), and no asset on disk may differ from its hash. Then
// twenty kills of a second instance while it takes a session and its mesh (2.4 MB) from another
// instance through Redis: after each it starts again and must serve the session whole.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include "bench_harness.hpp"
#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"
#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "net_load.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::vector<Result> run_crash_suite(Harness& harness) {
  const fs::path dir = fs::path(harness.options().output_dir.empty() ? "." : harness.options().output_dir) / "crash-bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string server_bin = program_beside_bench("inkwire-server");
  const std::string duck = "/usr/share/assimp/models/Collada/duck.dae";
  const fs::path data = dir / "data";
  std::ofstream(dir / "server.json") << R"({ "sessions": [ { "name": "scene", "kind": "scene" } ] })";
  std::mt19937 rng(20261125);
  std::vector<std::string> stored;  // products add-product said it stored
  int kills = 0, add_kills = 0, change_kills = 0, restarts_failed = 0;
  for (int i = 0; i < 100; ++i) {
    const auto log = dir / ("run-" + std::to_string(i) + ".log");
    if (i % 2 == 0) {
      // add-product of a product not made before (its size differs), killed somewhere in its work.
      const std::string name = "p" + std::to_string(i);
      const pid_t pid = spawn_process({server_bin, "add-product", name, "--mesh", duck, "--samples", "8", "--size", std::to_string(64 + 2 * i), "--data", data.string()}, log);
      std::this_thread::sleep_for(std::chrono::milliseconds(std::uniform_int_distribution<int>(50, 2500)(rng)));
      kill(pid, SIGKILL);
      int status = 0;
      waitpid(pid, &status, 0);
      const std::string said = text_of(log);
      if (said.find("stored product '" + name + "'") != std::string::npos || said.find("already stored: product '" + name + "'") != std::string::npos)
        stored.push_back(name);
      ++add_kills;
    } else {
      // A running server, a member changing the session as fast as it can, killed.
      const int port = free_loopback_port();
      const pid_t pid = spawn_process({server_bin, "--listen", "127.0.0.1:" + std::to_string(port), "--data", data.string(), "--config", (dir / "server.json").string(), "--quiet"}, log);
      for (int t = 0; t < 200 && !port_answers(port); ++t) std::this_thread::sleep_for(std::chrono::milliseconds(25));
      if (!port_answers(port)) {
        ++restarts_failed;  // the data a kill left behind does not start
      } else {
        try {
          SessionClient member("127.0.0.1:" + std::to_string(port), "changer");
          member.join("scene", "");
          const auto until = Clock::now() + std::chrono::milliseconds(std::uniform_int_distribution<int>(50, 1500)(rng));
          for (uint32_t k = 1; Clock::now() < until; ++k) {
            member.send(protocol::StyleChange{.renderer = k % 2 ? "comic" : "hatching", .settings = {}});
            member.send(orbit_pose(float(k % 360), 10, 1.4f, k));
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
          }
        } catch (const Error&) {
          ++restarts_failed;
        }
      }
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
      ++change_kills;
    }
    ++kills;
  }

  // The aftermath: the server starts on what the kills left; every stored product is served whole.
  const int port = free_loopback_port();
  const pid_t pid = spawn_process({server_bin, "--listen", "127.0.0.1:" + std::to_string(port), "--data", data.string(), "--config", (dir / "server.json").string(), "--quiet"},
                          dir / "after.log");
  for (int t = 0; t < 400 && !port_answers(port); ++t) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  int served = 0, lost = 0;
  if (port_answers(port)) {
    AssetCache cache(dir / "cache");
    for (const std::string& name : stored) {
      try {
        SessionClient visitor("127.0.0.1:" + std::to_string(port), "visitor");
        const protocol::Snapshot state = visitor.join(name, "");
        visitor.fetch_assets(state, cache);  // each checked against its hash
        ++served;
      } catch (const Error& e) {
        std::fprintf(stderr, "crash suite: product %s lost: %s\n", name.c_str(), e.what());
        ++lost;
      }
    }
  } else {
    lost = int(stored.size());
  }
  kill(pid, SIGTERM);
  waitpid(pid, nullptr, 0);
  // No asset on disk differs from its name's hash (what is named is whole).
  int partial = 0, assets = 0;
  for (const auto& e : fs::directory_iterator(data / "assets")) {
    ++assets;
    if (e.path().filename().string().find('.') != std::string::npos) continue;  // a temporary name, never served
    if (to_hex(content_hash_of_file(e.path())) != e.path().filename().string()) ++partial;
  }
  // Kills while an instance takes a session's assets from another through the broker.
  int upload_kills = 0, uploads_served = 0, uploads_lost = 0, killed_mid_upload = 0;
  {
    BrokerProcess broker(BrokerProcess::Kind::Redis);
    const std::string url = "redis://127.0.0.1:" + std::to_string(broker.port());
    std::ofstream(dir / "one.json") << R"({ "name": "one", "broker": ")" << url
                                    << R"(", "sessions": [ { "name": "bunny", "kind": "scene", "assets": [ { "path": "/usr/share/glmark2/models/bunny.obj" } ] } ] })";
    std::ofstream(dir / "two.json") << R"({ "name": "two", "broker": ")" << url << R"(", "sessions": [] })";
    const int one_port = free_loopback_port();
    const pid_t one = spawn_process({server_bin, "--listen", "127.0.0.1:" + std::to_string(one_port), "--data", (dir / "data-one").string(), "--config",
                             (dir / "one.json").string(), "--quiet"}, dir / "one.log");
    for (int t = 0; t < 400 && !port_answers(one_port); ++t) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    std::this_thread::sleep_for(std::chrono::seconds(2));  // one has shared the session and its mesh
    for (int i = 0; i < 20; ++i) {
      // Each time from nothing, so every kill can fall in the middle of taking the mesh; the
      // restart then finds whatever the kill left.
      fs::remove_all(dir / "data-two");
      const int port = free_loopback_port();
      const std::vector<std::string> two = {server_bin, "--listen", "127.0.0.1:" + std::to_string(port), "--data", (dir / "data-two").string(),
                                            "--config", (dir / "two.json").string()};
      const fs::path victim_log = dir / ("two-" + std::to_string(i) + ".log");
      const pid_t victim = spawn_process(two, victim_log);
      // The mesh comes within about 20 ms of the instance's listening: the kill falls in that window.
      for (int t = 0; t < 500 && text_of(victim_log).find("\"listening\"") == std::string::npos; ++t) std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::this_thread::sleep_for(std::chrono::microseconds(std::uniform_int_distribution<int>(0, 30000)(rng)));
      kill(victim, SIGKILL);
      if (text_of(victim_log).find("\"session-added\"") == std::string::npos) ++killed_mid_upload;
      waitpid(victim, nullptr, 0);
      ++upload_kills;
      // Started again: it takes the session (again, or from what it stored) and serves it whole.
      const pid_t again = spawn_process(two, dir / ("two-" + std::to_string(i) + "-again.log"));
      for (int t = 0; t < 400 && !port_answers(port); ++t) std::this_thread::sleep_for(std::chrono::milliseconds(25));
      bool served = false;
      for (int t = 0; t < 40 && !served; ++t) {
        try {
          SessionClient visitor("127.0.0.1:" + std::to_string(port), "visitor");
          const protocol::Snapshot state = visitor.join("bunny", "");
          AssetCache cache(dir / ("cache-two-" + std::to_string(i)));
          visitor.fetch_assets(state, cache);  // checked against its hash
          served = true;
        } catch (const Error&) {
          std::this_thread::sleep_for(std::chrono::milliseconds(250));  // not taken yet
        }
      }
      (served ? uploads_served : uploads_lost) += 1;
      kill(again, SIGKILL);
      waitpid(again, nullptr, 0);
    }
    kill(one, SIGTERM);
    waitpid(one, nullptr, 0);
    for (const auto& e : fs::directory_iterator(dir / "data-two" / "assets")) {  // the last run's
      if (e.path().filename().string().find('.') != std::string::npos) continue;
      if (to_hex(content_hash_of_file(e.path())) != e.path().filename().string()) ++partial;
    }
  }

  Result r{.suite = "crash", .renderer = "crash", .variant = "kills=" + std::to_string(kills + upload_kills), .object = "-"};
  r.counters = {{"kills", double(kills)}, {"add_product_kills", double(add_kills)}, {"session_change_kills", double(change_kills)},
                {"products_stored", double(stored.size())}, {"products_served", double(served)}, {"products_lost", double(lost)},
                {"restarts_failed", double(restarts_failed)}, {"assets_on_disk", double(assets)}, {"partial_assets_named", double(partial)},
                {"asset_upload_kills", double(upload_kills)}, {"uploaded_sessions_served", double(uploads_served)},
                {"uploaded_sessions_lost", double(uploads_lost)}, {"killed_before_the_session_was_taken", double(killed_mid_upload)}};
  return {r};
}

}  // namespace inkwire::bench
