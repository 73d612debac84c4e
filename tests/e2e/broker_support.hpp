#pragma once
// A throw-away Redis for the tests of several instances (tests/e2e/broker_e2e_test.cpp and
// others): loopback only, nothing saved, on a free port. Tests skip with a message without
// redis-server (Debian package redis-server).
#include <memory>
#include <string>
#include <vector>

#include "e2e_support.hpp"

namespace inkwire::e2e {

inline const fs::path kRedis = "/usr/bin/redis-server";

inline int free_port() {
  asio::io_context io;
  asio::ip::tcp::acceptor a(io, {asio::ip::make_address("127.0.0.1"), 0});
  return a.local_endpoint().port();
}

inline bool accepts(int port) {
  asio::io_context io;
  asio::ip::tcp::socket s(io);
  std::error_code ec;
  s.connect({asio::ip::make_address("127.0.0.1"), uint16_t(port)}, ec);
  return !ec;
}

// A throw-away Redis: loopback only, nothing saved, so a restart starts empty (the hardest
// case for the instances: they must put everything back).
class BrokerUnderTest {
 public:
  explicit BrokerUnderTest(const fs::path& dir, std::string password = "") : dir_(dir), port_(free_port()), password_(std::move(password)) { start(); }
  void start() {
    std::vector<std::string> args{"--port", std::to_string(port_), "--bind", "127.0.0.1", "--save", "", "--appendonly", "no", "--dir", dir_.string()};
    if (!password_.empty()) args.insert(args.end(), {"--requirepass", password_});
    process_ = std::make_unique<Process>(kRedis.string(), args, dir_ / ("redis-" + std::to_string(starts_++) + ".log"));
    ASSERT_TRUE(eventually([&] { return accepts(port_); })) << process_->output();
  }
  void kill() {
    process_->kill(SIGKILL);
    process_->wait();
  }
  // SIGSTOP / SIGCONT: a broker that stops answering with its sockets still open.
  void signal(int sig) { process_->kill(sig); }
  // A command of redis-cli's on this broker (e.g. SCRIPT FLUSH); its exit code.
  int cli(const std::vector<std::string>& command) const {
    std::vector<std::string> args{"-p", std::to_string(port_)};
    args.insert(args.end(), command.begin(), command.end());
    Process p("/usr/bin/redis-cli", args, dir_ / "redis-cli.log");
    return p.wait();
  }
  std::string url(const std::string& password = "") const {
    return "redis://" + (password.empty() ? "" : ":" + password + "@") + "127.0.0.1:" + std::to_string(port_);
  }

 private:
  fs::path dir_;
  int port_;
  std::string password_;
  int starts_ = 0;
  std::unique_ptr<Process> process_;
};

}  // namespace inkwire::e2e
