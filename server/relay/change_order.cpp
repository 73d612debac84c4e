#include "server/relay/change_order.hpp"

#include <algorithm>
#include <utility>

namespace inkwire::server {

ChangeOrder::Arrival ChangeOrder::arrive(BrokerEvent event) {
  if (syncing_) return {.dropped = wait(std::move(event))};
  if (event.revision <= revision_) return {};  // in the state a resync read already
  if (event.revision != revision_ + 1) return {.resync = true, .dropped = wait(std::move(event))};  // one was missed
  revision_ = event.revision;
  return {.apply = std::move(event)};
}

size_t ChangeOrder::wait(BrokerEvent event) {
  // Bounded: past kMaxWaiting the waiting changes are dropped, and the resync under way (or the
  // one asked for with this) brings the state whole instead.
  size_t dropped = 0;
  if (waiting_.size() >= kMaxWaiting) dropped = std::exchange(waiting_, {}).size();
  waiting_.push_back(std::move(event));
  return dropped;
}

void ChangeOrder::broker_lost() {
  syncing_ = false;
  waiting_.clear();
}

ChangeOrder::Resynced ChangeOrder::resynced(uint32_t revision) {
  revision_ = revision;
  syncing_ = false;
  std::vector<BrokerEvent> waiting = std::exchange(waiting_, {});
  std::stable_sort(waiting.begin(), waiting.end(), [](const BrokerEvent& a, const BrokerEvent& b) { return a.revision < b.revision; });
  Resynced out;
  for (BrokerEvent& e : waiting) {
    if (out.resync) {  // behind a gap: they wait for the next resync
      wait(std::move(e));
      continue;
    }
    Arrival a = arrive(std::move(e));
    if (a.apply) out.apply.push_back(std::move(*a.apply));
    out.resync = a.resync;
  }
  return out;
}

}  // namespace inkwire::server
