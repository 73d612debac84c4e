#pragma once
// Who the server takes on (SPEC D3): every client holds a place while it is served (a
// connection, or an HTTP request being read), within a cap overall and one per address; and
// wrong tokens from one address slow that address's joins down. Touched on the I/O thread only.
#include <chrono>
#include <cstdint>
#include <map>
#include <string>

#include "server/config.hpp"

namespace inkwire::server {

class Admission {
 public:
  explicit Admission(const ServerConfig& config) : config_(config) {}

  // Past a cap (max_connections, or max_connections_per_address) the place is still taken, and
  // the reason to refuse the newcomer returned; empty when it may be served. Each place taken
  // is given back once.
  std::string take_place(const std::string& address);
  void give_place(const std::string& address);

  // None for the first few wrong tokens, then doubling up to a cap; a right token clears the
  // count, and a quiet while forgives it.
  std::chrono::milliseconds join_delay(const std::string& address);
  void join_failed(const std::string& address);
  void join_succeeded(const std::string& address) { join_failures_.erase(address); }

  // Whether the per-address limits apply to `address`: not to this machine's own (a local proxy
  // speaks for many people) unless the config says so.
  bool limited(const std::string& address) const;

  // For /metrics, since the start.
  uint64_t connections_refused() const { return connections_refused_; }  // past a connection cap
  uint64_t joins_refused() const { return joins_refused_; }              // wrong token

 private:
  const ServerConfig& config_;
  size_t places_ = 0;
  std::map<std::string, size_t> places_per_address_;
  struct JoinFailures {
    int count = 0;
    std::chrono::steady_clock::time_point last;
  };
  std::map<std::string, JoinFailures> join_failures_;
  uint64_t connections_refused_ = 0, joins_refused_ = 0;
};

}  // namespace inkwire::server
