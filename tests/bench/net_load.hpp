#pragma once
// What the net suite's rows share (suite_net.cpp, suite_net_instances.cpp): the load's shape,
// simulated clients on the real wire protocol, percentiles, CPU time of threads and processes,
// and a broker process (Redis or NATS) started on a free loopback port for one run.
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <asio.hpp>

namespace inkwire::bench {

using Clock = std::chrono::steady_clock;

struct LoadShape {
  int clients, sessions, hz;
  double seconds;
  std::string variant() const {
    return "clients=" + std::to_string(clients) + ",sessions=" + std::to_string(sessions) + ",hz=" + std::to_string(hz);
  }
};

// Everything the simulated clients share; touched only on the clients' I/O thread.
struct Load {
  LoadShape shape;
  std::vector<std::vector<Clock::time_point>> sent;  // [session][sequence]
  std::vector<std::vector<double>> latencies_ms;     // [instance the receiver is on]
  int64_t stalls = 0, delivered = 0, joined = 0, failed = 0;
  Load(const LoadShape& s, size_t instances)
      : shape(s), sent(size_t(s.sessions), std::vector<Clock::time_point>(size_t(s.seconds * s.hz))), latencies_ms(instances) {}
  // Deliveries every receiver should see.
  double expected() const { return double(shape.clients - shape.sessions) * double(sent[0].size()); }
};

// One simulated client of session index % sessions. The session's first client (on
// servers[0]) sends a camera pose at R Hz once everyone has joined; the others, spread over the
// servers in turn, time each pose's delivery and count gaps over three periods as stalls.
asio::awaitable<void> simulated_client(std::vector<asio::ip::tcp::endpoint> servers, Load& load, int index);

double percentile(std::vector<double> v, double p);
double thread_cpu_seconds();
double process_cpu_seconds(pid_t pid);  // user + system time of another process
double process_rss_mb(pid_t pid);        // resident memory of another process, from /proc
double process_open_fds(pid_t pid);      // its open descriptors
// The path of program `name` (inkwire-server) beside this inkwire-bench: a copied set of the
// three runs as one, whatever the build tree does meanwhile.
std::string program_beside_bench(const std::string& name);
// Starts a program (args[0] a path) with stdout and stderr in `log`; its pid.
pid_t spawn_process(const std::vector<std::string>& args, const std::string& log);
int free_loopback_port();
// Whether something accepts connections on 127.0.0.1:`port` now (a server process started yet).
bool port_answers(int port);

// A broker started for one run: redis-server (nothing saved) or nats-server on 127.0.0.1.
class BrokerProcess {
 public:
  enum class Kind { Redis, Nats };
  // Throws inkwire::Error when the program is missing or does not start listening.
  explicit BrokerProcess(Kind kind);
  ~BrokerProcess();
  // Killed without warning and started again on the same port (what it held is gone).
  void restart();
  BrokerProcess(const BrokerProcess&) = delete;
  BrokerProcess& operator=(const BrokerProcess&) = delete;
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  double cpu_seconds() const { return process_cpu_seconds(pid_); }

 private:
  void start();

  Kind kind_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace inkwire::bench
