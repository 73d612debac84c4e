// inkwire-bench --suite soak --minutes M (SPEC D8): two real inkwire-server processes sharing
// their sessions through a real redis-server, under churn for M minutes, as an operator's week
// would have it in little:
//  - steady traffic: a presenter on each of five scene sessions sends a pose 10 times a second
//    to the first instance, watched by two members on each instance (their latency is p99_ms);
//  - visitors join a scene session on either instance five times a second and stay 1-8 s, half
//    leaving politely, half dropping their connection;
//  - call members join the call on either instance every 2 s and speak (Opus packets of a
//    tone) for 3-10 s; a third of them then leave, a third drop the connection, and a third go
//    silent without closing (no reading, no writing), which only the server's deadlines end;
//  - a style change on a scene session every 5 s, acknowledged when a member of that session on
//    the same instance receives it;
//  - products added by `add-product` beside the running first instance, and the older ones taken
//    out by `remove-product`;
//  - the broker killed and started again at a third of the run, the second instance killed
//    (SIGKILL) and started again at two thirds.
// Then the crowd leaves; after the deadlines have passed: the first instance's memory and
// descriptors against the start (steady traffic alone), no ghost in either instance's roster,
// and nothing acknowledged lost (every acknowledged last style on both instances, every product
// stored and not removed served, every removed one refused).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <thread>

#include <asio.hpp>
#include <asio/experimental/as_tuple.hpp>
#include <nlohmann/json.hpp>

#include "bench_harness.hpp"
#include "client/call/voice_codec.hpp"
#include "client/net/session_client.hpp"
#include "common/error.hpp"
#include "net_load.hpp"
#include "protocol/framing.hpp"

namespace inkwire::bench {
namespace {

namespace fs = std::filesystem;
using namespace protocol;
using asio::ip::tcp;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);
constexpr int kSteadySessions = 5, kChurnSessions = 5, kPoseHz = 10;
const std::vector<std::string> kStyles = {"comic", "hatching", "sketch", "default"};

std::string scene_name(int i) { return "s" + std::to_string(i); }

// One inkwire-server instance on a fixed loopback port, its data and log in `dir`.
class Instance {
 public:
  Instance(const fs::path& dir, const std::string& name, const std::string& broker) : dir_(dir), port_(free_loopback_port()) {
    nlohmann::json sessions = nlohmann::json::array({{{"name", "call"}, {"kind", "conference"}}});
    for (int i = 0; i < kSteadySessions + kChurnSessions; ++i) sessions.push_back({{"name", scene_name(i)}, {"kind", "scene"}});
    fs::create_directories(dir);
    std::ofstream(dir / "server.json") << nlohmann::json{{"name", name}, {"broker", broker}, {"sessions", sessions}}.dump();
    start();
  }
  ~Instance() { stop(SIGTERM); }
  void start() {
    const std::string bin = program_beside_bench("inkwire-server");
    pid_ = spawn_process({bin, "--listen", "127.0.0.1:" + std::to_string(port_), "--config", (dir_ / "server.json").string(), "--data",
                          (dir_ / "data").string(), "--quiet"},
                         (dir_ / ("server-" + std::to_string(starts_++) + ".log")).string());
    for (int i = 0; i < 400 && !port_answers(port_); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    if (!port_answers(port_)) throw Error("inkwire-server did not start (see " + dir_.string() + ")");
  }
  void stop(int signal) {
    if (pid_ <= 0) return;
    kill(pid_, signal);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  pid_t pid() const { return pid_; }
  tcp::endpoint endpoint() const { return {asio::ip::make_address("127.0.0.1"), uint16_t(port_)}; }
  std::string host_port() const { return "127.0.0.1:" + std::to_string(port_); }
  fs::path data() const { return dir_ / "data"; }

 private:
  fs::path dir_;
  int port_;
  pid_t pid_ = -1;
  int starts_ = 0;
};

// A connection speaking the protocol as a client does: writes go out one after another (a
// reader answering pings and a sender share the socket), reads are split into messages.
class Peer : public std::enable_shared_from_this<Peer> {
 public:
  explicit Peer(asio::any_io_executor executor) : socket(executor), chunk_(4096) {}
  tcp::socket socket;

  void send(const Message& message) {
    outbox_.push_back(encode(message));
    if (writing_) return;
    writing_ = true;
    asio::co_spawn(socket.get_executor(), [self = shared_from_this()]() -> asio::awaitable<void> {
      while (!self->outbox_.empty()) {
        const Bytes frame = std::move(self->outbox_.front());
        self->outbox_.pop_front();
        auto [ec, n] = co_await asio::async_write(self->socket, asio::buffer(frame), no_throw);
        if (ec) break;
      }
      self->outbox_.clear();
      self->writing_ = false;
    }, asio::detached);
  }
  // The next message that is not a ping (pings are answered here); nothing once the connection ends.
  asio::awaitable<std::optional<Message>> next() {
    for (;;) {
      while (std::optional<Message> m = frames_.next()) {
        if (const auto* ping = std::get_if<Ping>(&*m)) send(Pong{.nonce = ping->nonce});
        else co_return m;
      }
      auto [ec, n] = co_await socket.async_read_some(asio::buffer(chunk_), no_throw);
      if (ec) co_return std::nullopt;
      frames_.feed(chunk_.data(), n);
    }
  }
  void close() {
    std::error_code ignored;
    socket.shutdown(tcp::socket::shutdown_both, ignored);
    socket.close(ignored);
  }

 private:
  std::vector<uint8_t> chunk_;
  FrameDecoder frames_;
  std::deque<Bytes> outbox_;
  bool writing_ = false;
};

// Connects, says hello and joins; the peer once the snapshot came, null if anything failed.
// Callers pass names held in locals: GCC 12 mishandles temporaries that live across a co_await
// (which is also why coroutines here take their executor apart, and functions as locals).
asio::awaitable<std::shared_ptr<Peer>> join(tcp::endpoint at, const std::string& name, const std::string& session) {
  const auto executor = co_await asio::this_coro::executor;
  auto peer = std::make_shared<Peer>(executor);
  auto [ec] = co_await peer->socket.async_connect(at, no_throw);
  if (ec) co_return nullptr;
  peer->socket.set_option(tcp::no_delay(true));
  peer->send(Hello{.client_name = name});
  peer->send(Join{.session = session, .token = ""});
  for (;;) {
    auto m = co_await peer->next();
    if (!m || std::holds_alternative<ErrorMessage>(*m)) co_return nullptr;
    if (std::holds_alternative<Snapshot>(*m)) co_return peer;
  }
}

asio::awaitable<void> sleep_for(Clock::duration d) {
  const auto executor = co_await asio::this_coro::executor;
  asio::steady_timer timer(executor, d);
  co_await timer.async_wait(no_throw);
}

// Everything the client coroutines share; touched on the clients' I/O thread only.
struct Soak {
  std::vector<Instance*> instances;
  Clock::time_point churn_until, steady_until;
  std::mt19937 rng{20261128};
  std::vector<std::vector<Clock::time_point>> sent;  // [steady session][pose sequence]
  std::vector<double> latencies_ms;
  int64_t poses_sent = 0, poses_delivered = 0;
  int64_t visitors_joined = 0, visitors_refused = 0, members_joined = 0, members_silent = 0;
  std::vector<Bytes> voice;  // Opus packets of a tone, sent round and round
  std::map<std::string, std::vector<std::string>> roster;  // observer -> the names in its newest roster
  tcp::endpoint at(size_t instance) const { return instances[instance]->endpoint(); }
};

// A presenter of steady session `session` on the first instance: a pose every 100 ms; joins
// again after a lost connection.
asio::awaitable<void> presenter(Soak& soak, int session) {
  const auto executor = co_await asio::this_coro::executor;  // apart: GCC 12 and co_await inside a longer expression
  const std::string name = "presenter-" + std::to_string(session), scene = scene_name(session);
  uint32_t sequence = 0;
  while (Clock::now() < soak.steady_until) {
    auto peer = co_await join(soak.at(0), name, scene);
    if (!peer) {
      co_await sleep_for(std::chrono::milliseconds(500));
      continue;
    }
    asio::co_spawn(executor, [peer]() -> asio::awaitable<void> {
      while (co_await peer->next()) {}  // answers pings
      peer->close();                    // the server ended it: join again
    }, asio::detached);
    auto next = Clock::now();
    while (Clock::now() < soak.steady_until && peer->socket.is_open() && sequence < soak.sent[size_t(session)].size()) {
      next += std::chrono::milliseconds(1000 / kPoseHz);
      asio::steady_timer timer(executor, next);
      co_await timer.async_wait(no_throw);
      soak.sent[size_t(session)][sequence] = Clock::now();
      peer->send(CameraPose{.sequence = sequence++, .position = {0, 1, 10}, .target = {0, 0, 0}, .up = {0, 1, 0}, .fov_y_degrees = 45});
      ++soak.poses_sent;
    }
    peer->close();
  }
}

// A member of `session` on one instance until the steady traffic ends, joining again after a
// lost connection (an instance killed), each message it gets handed to `heard`.
asio::awaitable<void> stay_joined(Soak& soak, size_t instance, const std::string& name, const std::string& session,
                                  const std::function<void(const Message&)>& heard) {
  const auto executor = co_await asio::this_coro::executor;  // apart: GCC 12 and co_await inside a longer expression
  while (Clock::now() < soak.steady_until) {
    auto peer = co_await join(soak.at(instance), name, session);
    if (!peer) {
      co_await sleep_for(std::chrono::milliseconds(500));
      continue;
    }
    asio::steady_timer done(executor, soak.steady_until);
    done.async_wait([peer](std::error_code) { peer->close(); });
    while (auto m = co_await peer->next()) heard(*m);
    done.cancel();
  }
}

// A member watching steady session `session` on one instance, timing each pose.
asio::awaitable<void> watcher(Soak& soak, int session, size_t instance) {
  const std::string name = "watcher-" + std::to_string(session), scene = scene_name(session);
  const std::function<void(const Message&)> timed = [&soak, session](const Message& m) {
    const auto* pose = std::get_if<CameraPose>(&m);
    if (!pose || pose->sequence >= soak.sent[size_t(session)].size()) return;
    const Clock::time_point sent = soak.sent[size_t(session)][pose->sequence];
    if (sent == Clock::time_point{}) return;
    soak.latencies_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - sent).count());
    ++soak.poses_delivered;
  };
  co_await stay_joined(soak, instance, name, scene, timed);
}

// A member of the call on one instance for the whole run, keeping the names of its newest roster.
asio::awaitable<void> call_observer(Soak& soak, size_t instance) {
  const std::string name = "observer-" + std::to_string(instance), call = "call";
  const std::function<void(const Message&)> kept = [&soak, &name](const Message& m) {
    const auto* roster = std::get_if<Roster>(&m);
    if (!roster) return;
    std::vector<std::string>& names = soak.roster[name];
    names.clear();
    for (const CallMember& member : roster->members) names.push_back(member.name);
  };
  co_await stay_joined(soak, instance, name, call, kept);
}

// A visitor of a churn session: stays a while, then leaves politely or just drops.
asio::awaitable<void> visitor(Soak& soak, int index) {
  const auto executor = co_await asio::this_coro::executor;  // apart: GCC 12 and co_await inside a longer expression
  std::uniform_int_distribution<int> instance(0, 1), session(kSteadySessions, kSteadySessions + kChurnSessions - 1), stay(1000, 8000);
  const size_t at = size_t(instance(soak.rng));
  const int s = session(soak.rng), ms = stay(soak.rng);
  const bool polite = index % 2 == 0;
  const std::string name = "visitor-" + std::to_string(index), scene = scene_name(s);
  auto peer = co_await join(soak.at(at), name, scene);
  if (!peer) {
    ++soak.visitors_refused;  // the instance is down (killed and not back yet)
    co_return;
  }
  ++soak.visitors_joined;
  asio::steady_timer done(executor, std::chrono::milliseconds(ms));
  done.async_wait([peer, polite](std::error_code) {
    if (polite) peer->send(Leave{});
    peer->close();
  });
  while (co_await peer->next()) {}
}

// A call member: publishes its voice for a while, then leaves, drops, or goes silent while
// holding the connection open (for longer than the server's deadline).
asio::awaitable<void> call_member(Soak& soak, int index) {
  const auto executor = co_await asio::this_coro::executor;  // apart: GCC 12 and co_await inside a longer expression
  std::uniform_int_distribution<int> instance(0, 1), stay(3000, 10000);
  const size_t at = size_t(instance(soak.rng));
  const int ms = stay(soak.rng), ending = index % 3;
  const std::string name = "member-" + std::to_string(index), call = "call";
  auto peer = co_await join(soak.at(at), name, call);
  if (!peer) co_return;
  ++soak.members_joined;
  auto ended = std::make_shared<bool>(false);
  asio::co_spawn(executor, [peer, ended]() -> asio::awaitable<void> {
    while (co_await peer->next()) {}
    *ended = true;
  }, asio::detached);
  peer->send(Publish{.camera = false, .microphone = true});
  const auto until = Clock::now() + std::chrono::milliseconds(ms);
  for (uint32_t k = 0; Clock::now() < until && !*ended; ++k) {
    peer->send(VoiceFrame{.member = 0, .time_ms = k * 60, .opus = soak.voice[k % soak.voice.size()]});
    co_await sleep_for(std::chrono::milliseconds(60));
  }
  if (ending == 0) {
    peer->send(Leave{});
    co_await sleep_for(std::chrono::milliseconds(100));
  } else if (ending == 2 && !*ended) {
    // Silent: nothing read (the server's pings go unanswered) and nothing written, the
    // connection held open past the server's 15 s deadline.
    ++soak.members_silent;
    std::error_code ignored;
    peer->socket.cancel(ignored);
    co_await sleep_for(std::chrono::seconds(25));
  }
  peer->close();
}

// Starts visitors (5 a second) and call members (one every 2 s) until the churn ends.
asio::awaitable<void> churn(Soak& soak) {
  auto executor = co_await asio::this_coro::executor;
  for (int tick = 0; Clock::now() < soak.churn_until; ++tick) {
    asio::co_spawn(executor, visitor(soak, tick), asio::detached);
    if (tick % 10 == 0) asio::co_spawn(executor, call_member(soak, tick / 10), asio::detached);
    co_await sleep_for(std::chrono::milliseconds(200));
  }
}

std::vector<Bytes> tone_packets() {
  VoiceEncoder encoder(60, 10000);
  std::vector<Bytes> packets;
  std::vector<float> frame(size_t(encoder.frame_samples()));
  for (int p = 0; p < 20; ++p) {
    for (size_t i = 0; i < frame.size(); ++i)
      frame[i] = 0.3f * float(std::sin(2 * M_PI * 220.0 * double(size_t(p) * frame.size() + i) / 48000.0));
    packets.push_back(encoder.encode(frame));
  }
  return packets;
}

// What the operator's thread acknowledged and must find at the end.
struct Acknowledged {
  std::map<std::string, std::string> styles;       // churn session -> last style a member received
  std::vector<std::string> products, removed;      // stored (and not removed), removed
  int style_changes = 0, products_added = 0, products_removed = 0;
  int unacknowledged = 0;                          // changes no member was seen to receive
};

// A style change on `session` at `instance`, acknowledged when another member there receives it.
void change_style(Instance& instance, const std::string& session, const std::string& style, Acknowledged& ack) {
  try {
    SessionClient member(instance.host_port(), "editor"), witness(instance.host_port(), "witness");
    member.join(session, "");
    witness.join(session, "");
    uint64_t seen = witness.updates();
    member.send(StyleChange{.renderer = style, .settings = {}});
    const auto until = Clock::now() + std::chrono::seconds(5);
    while (Clock::now() < until && witness.state().style.renderer != style)
      seen = witness.wait_for_update(seen, std::chrono::milliseconds(200));
    ++ack.style_changes;
    if (witness.state().style.renderer == style) ack.styles[session] = style;
    else ++ack.unacknowledged;
  } catch (const Error&) {
    ++ack.unacknowledged;  // the instance is down: nothing was acknowledged
  }
}

bool serves(const Instance& instance, const std::string& session) {
  try {
    SessionClient visitor(instance.host_port(), "checker");
    visitor.join(session, "");
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

std::vector<Result> run_soak_suite(Harness& harness) {
  const double minutes = harness.options().minutes;
  const fs::path dir = fs::path(harness.options().output_dir.empty() ? "." : harness.options().output_dir) / "soak-bench";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string server_bin = program_beside_bench("inkwire-server");
  const std::string duck = "/usr/share/assimp/models/Collada/duck.dae";
  BrokerProcess broker(BrokerProcess::Kind::Redis);
  const std::string url = "redis://127.0.0.1:" + std::to_string(broker.port());
  Instance first(dir / "a", "soak-a", url), second(dir / "b", "soak-b", url);

  const auto run = std::chrono::milliseconds(int64_t(minutes * 60000));
  const auto settle = std::chrono::seconds(5);
  const auto start = Clock::now();
  Soak soak;
  soak.instances = {&first, &second};
  soak.churn_until = start + settle + run;
  soak.voice = tone_packets();
  const auto drain = std::chrono::seconds(40);  // silent members held 25 s, then the 15 s deadline
  soak.steady_until = soak.churn_until + drain;
  soak.sent.assign(kSteadySessions, std::vector<Clock::time_point>(size_t(std::chrono::duration<double>(settle + run + drain).count() * kPoseHz + 100)));

  asio::io_context io(1);
  for (int s = 0; s < kSteadySessions; ++s) {
    asio::co_spawn(io, presenter(soak, s), asio::detached);
    for (size_t i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k) asio::co_spawn(io, watcher(soak, s, i), asio::detached);
  }
  for (size_t i = 0; i < 2; ++i) asio::co_spawn(io, call_observer(soak, i), asio::detached);
  asio::steady_timer churn_start(io, start + settle);
  churn_start.async_wait([&](std::error_code) { asio::co_spawn(io, churn(soak), asio::detached); });
  std::thread clients([&] { io.run(); });

  // The operator's thread: figures, style changes, products, the broker and the second instance.
  std::this_thread::sleep_for(settle - std::chrono::milliseconds(500));
  const double rss_start = process_rss_mb(first.pid()), fds_start = process_open_fds(first.pid());
  double rss_peak = rss_start;
  Acknowledged ack;
  bool broker_restarted = false, instance_killed = false;
  const auto product_every = std::chrono::milliseconds(std::max<int64_t>(20000, run.count() / 10));
  auto next_product = start + settle + std::chrono::seconds(10), next_style = start + settle;
  int tick = 0;
  while (Clock::now() < soak.churn_until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    rss_peak = std::max(rss_peak, process_rss_mb(first.pid()));
    const double done = std::chrono::duration<double>(Clock::now() - start - settle) / run;
    if (!broker_restarted && done >= 1.0 / 3) {
      std::fprintf(stderr, "  soak: the broker killed and started again\n");
      broker.restart();
      broker_restarted = true;
    }
    if (!instance_killed && done >= 2.0 / 3) {
      std::fprintf(stderr, "  soak: the second instance killed (SIGKILL), started again in 2 s\n");
      second.stop(SIGKILL);
      std::this_thread::sleep_for(std::chrono::seconds(2));
      second.start();
      instance_killed = true;
    }
    if (Clock::now() >= next_style) {
      const int session = kSteadySessions + tick % kChurnSessions;
      change_style(tick % 2 ? second : first, scene_name(session), kStyles[size_t(tick / kChurnSessions) % kStyles.size()] , ack);
      ++tick;
      next_style += std::chrono::seconds(5);
    }
    if (Clock::now() >= next_product) {
      // A product added beside the running first instance; every second one, the oldest removed.
      const std::string name = "p" + std::to_string(ack.products_added);
      const pid_t add = spawn_process({server_bin, "add-product", name, "--mesh", duck, "--samples", "6", "--size", "64", "--data", first.data().string()},
                                      (dir / (name + ".log")).string());
      int status = 0;
      waitpid(add, &status, 0);
      ++ack.products_added;
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) ack.products.push_back(name);
      if (ack.products_added % 2 == 0 && ack.products.size() > 1) {
        const std::string old = ack.products.front();
        const pid_t remove = spawn_process({server_bin, "remove-product", old, "--data", first.data().string()}, (dir / (old + "-removed.log")).string());
        waitpid(remove, &status, 0);
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
          ack.products.erase(ack.products.begin());
          ack.removed.push_back(old);
          ++ack.products_removed;
        }
      }
      next_product += product_every;
    }
  }
  std::fprintf(stderr, "  soak: the crowd leaves; waiting %d s for the deadlines\n", int(std::chrono::duration_cast<std::chrono::seconds>(drain).count()));
  std::this_thread::sleep_until(soak.churn_until + drain - std::chrono::seconds(2));
  // Once the crowd has gone and every deadline passed: the figures, the rosters, what was acknowledged.
  const double rss_end = process_rss_mb(first.pid()), fds_end = process_open_fds(first.pid());
  const double rss_second = process_rss_mb(second.pid()), fds_second = process_open_fds(second.pid());
  clients.join();  // the steady traffic ends; the observers keep their newest rosters
  int ghosts = 0;
  for (const auto& [observer, names] : soak.roster)
    for (const std::string& name : names)
      if (name.rfind("observer-", 0) != 0) {
        std::fprintf(stderr, "  soak: %s still lists %s\n", observer.c_str(), name.c_str());
        ++ghosts;
      }
  int lost = 0;
  for (Instance* instance : soak.instances)
    for (const auto& [session, style] : ack.styles) {
      try {
        SessionClient late(instance->host_port(), "late");
        if (late.join(session, "").style.renderer != style) {
          std::fprintf(stderr, "  soak: %s on %s shows another style than %s, the last acknowledged\n", session.c_str(), instance->host_port().c_str(), style.c_str());
          ++lost;
        }
      } catch (const Error& e) {
        std::fprintf(stderr, "  soak: %s on %s: %s\n", session.c_str(), instance->host_port().c_str(), e.what());
        ++lost;
      }
    }
  for (const std::string& name : ack.products)
    if (!serves(first, name)) std::fprintf(stderr, "  soak: product %s, stored, is not served\n", name.c_str()), ++lost;
  int removed_served = 0;
  for (const std::string& name : ack.removed) removed_served += serves(first, name);

  Result r{.suite = "soak", .renderer = "soak", .variant = "minutes=" + nlohmann::json(minutes).dump(), .object = "-"};
  r.counters = {{"rss_mb_start", rss_start}, {"rss_mb_peak", rss_peak}, {"rss_mb_end", rss_end}, {"fds_start", fds_start}, {"fds_end", fds_end},
                {"second_rss_mb_end", rss_second}, {"second_fds_end", fds_second},
                {"ghost_members", double(ghosts)}, {"lost_acknowledged", double(lost)}, {"removed_products_served", double(removed_served)},
                {"p99_ms", percentile(soak.latencies_ms, 0.99)}, {"p50_ms", percentile(soak.latencies_ms, 0.50)},
                {"poses_sent", double(soak.poses_sent)}, {"poses_delivered", double(soak.poses_delivered)},
                {"delivered_fraction", soak.poses_sent ? double(soak.poses_delivered) / double(4 * soak.poses_sent) : 0},
                {"visitors_joined", double(soak.visitors_joined)}, {"visitors_refused", double(soak.visitors_refused)},
                {"call_members_joined", double(soak.members_joined)}, {"call_members_silent", double(soak.members_silent)},
                {"style_changes", double(ack.style_changes)}, {"style_changes_unacknowledged", double(ack.unacknowledged)},
                {"products_added", double(ack.products_added)}, {"products_removed", double(ack.products_removed)},
                {"broker_restarts", double(broker_restarted)}, {"instance_kills", double(instance_killed)}};
  std::fprintf(stderr, "  soak %.4g min: rss %.1f -> %.1f MB (peak %.1f), fds %.0f -> %.0f, ghosts %d, lost %d, p99 %.1f ms\n", minutes, rss_start, rss_end,
               rss_peak, fds_start, fds_end, ghosts, lost, r.counters["p99_ms"]);
  return {r};
}

}  // namespace inkwire::bench
