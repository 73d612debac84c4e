#include "server/admission.hpp"

#include <algorithm>

#include <asio/ip/address.hpp>

namespace inkwire::server {

std::string Admission::take_place(const std::string& address) {
  ++places_;
  const size_t from_address = ++places_per_address_[address];
  std::string refusal;
  if (places_ > config_.max_connections)
    refusal = "the server is full (" + std::to_string(config_.max_connections) + " connections)";
  else if (limited(address) && from_address > config_.max_connections_per_address)
    refusal = "too many connections from " + address + " (" + std::to_string(config_.max_connections_per_address) + ")";
  if (!refusal.empty()) ++connections_refused_;
  return refusal;
}

void Admission::give_place(const std::string& address) {
  --places_;
  if (--places_per_address_[address] == 0) places_per_address_.erase(address);
}

bool Admission::limited(const std::string& address) const {
  std::error_code ec;
  const auto ip = asio::ip::make_address(address, ec);
  return config_.limit_loopback || ec || !ip.is_loopback();
}

std::chrono::milliseconds Admission::join_delay(const std::string& address) {
  const auto it = join_failures_.find(address);
  if (it == join_failures_.end()) return {};
  // Forgiven after a quiet while; the map never outgrows the addresses that guessed lately.
  if (std::chrono::steady_clock::now() - it->second.last > std::chrono::minutes(10)) {
    join_failures_.erase(it);
    return {};
  }
  const int over = it->second.count - config_.join_failures_allowed;  // 0: the first join to slow down
  if (over < 0) return {};
  return std::chrono::milliseconds(std::min<int64_t>(int64_t(250) << std::min(over, 10), 8000));
}

void Admission::join_failed(const std::string& address) {
  ++joins_refused_;
  if (!limited(address)) return;
  JoinFailures& f = join_failures_[address];
  ++f.count;
  f.last = std::chrono::steady_clock::now();
}

}  // namespace inkwire::server
