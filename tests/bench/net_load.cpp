#include "net_load.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include <asio/experimental/as_tuple.hpp>

#include "common/error.hpp"
#include "protocol/framing.hpp"

extern char** environ;

namespace inkwire::bench {
namespace {

using namespace protocol;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

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

}  // namespace

asio::awaitable<void> simulated_client(std::vector<asio::ip::tcp::endpoint> servers, Load& load, int index) {
  const int session = index % load.shape.sessions;
  const bool sender = index < load.shape.sessions;
  const size_t instance = sender ? 0 : size_t(index / load.shape.sessions) % servers.size();
  asio::ip::tcp::socket s(co_await asio::this_coro::executor);
  auto [ec] = co_await s.async_connect(servers[instance], no_throw);
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
    if (!pose || pose->sequence >= load.sent[size_t(session)].size()) continue;
    const auto now = Clock::now();
    load.latencies_ms[instance].push_back(std::chrono::duration<double, std::milli>(now - load.sent[size_t(session)][pose->sequence]).count());
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

double process_cpu_seconds(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Fields after the command name (which may hold spaces) start after its closing parenthesis;
  // utime and stime are fields 14 and 15.
  const size_t close = text.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(text.substr(close + 2));
  std::string skip;
  for (int i = 3; i < 14; ++i) fields >> skip;
  double user = 0, system = 0;
  fields >> user >> system;
  return (user + system) / double(sysconf(_SC_CLK_TCK));
}

double process_rss_mb(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0;
}

double process_open_fds(pid_t pid) {
  double n = 0;
  std::error_code ec;
  for (std::filesystem::directory_iterator it("/proc/" + std::to_string(pid) + "/fd", ec), end; !ec && it != end; it.increment(ec)) ++n;
  return n;
}

std::string program_beside_bench(const std::string& name) {
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / name).string();
}

pid_t spawn_process(const std::vector<std::string>& args, const std::string& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  // Nothing else of this process goes with it: a client's socket held open by a server started
  // mid-run would keep that connection alive after the client closed it.
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw Error("cannot start " + args[0]);
  return pid;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * double(v.size())))];
}

bool port_answers(int port) {
  asio::io_context io;
  asio::ip::tcp::socket s(io);
  std::error_code ec;
  s.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)}, ec);
  return !ec;
}

int free_loopback_port() {
  asio::io_context io;
  asio::ip::tcp::acceptor a(io, {asio::ip::make_address("127.0.0.1"), 0});
  return a.local_endpoint().port();
}

BrokerProcess::BrokerProcess(Kind kind) : kind_(kind), port_(free_loopback_port()) { start(); }

void BrokerProcess::start() {
  const std::string port = std::to_string(port_);
  std::vector<std::string> args =
      kind_ == Kind::Redis ? std::vector<std::string>{"/usr/bin/redis-server", "--port", port, "--bind", "127.0.0.1", "--save", "", "--appendonly", "no",
                                                      "--maxclients", "4064", "--loglevel", "warning"}
                           : std::vector<std::string>{"/usr/sbin/nats-server", "-a", "127.0.0.1", "-p", port};
  if (access(args[0].c_str(), X_OK) != 0) throw Error(args[0] + " is missing (Debian package " + (kind_ == Kind::Redis ? "redis-server" : "nats-server") + ")");
  pid_ = spawn_process(args, "/dev/null");
  for (int i = 0; i < 200; ++i) {
    if (port_answers(port_)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  throw Error(args[0] + " did not start listening on port " + port);
}

void BrokerProcess::restart() {
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  start();
}

BrokerProcess::~BrokerProcess() {
  if (pid_ <= 0) return;
  kill(pid_, SIGTERM);
  waitpid(pid_, nullptr, 0);
}

}  // namespace inkwire::bench
