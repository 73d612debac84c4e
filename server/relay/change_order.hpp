#pragma once
// The order in which one session's changes from the broker are applied here: the broker numbers
// every change of a session (its revision), and each instance applies them one after another in
// that order. A change that skips a number means one was missed: the session's state is then read
// whole from the broker (a resync), and the changes that come meanwhile wait for it, to be
// applied in order after it. Only what to do is decided here, with no broker and no socket, so
// RedisRelay's ordering is tested on its own (tests/unit/change_order_test.cpp).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "server/relay/broker_formats.hpp"

namespace inkwire::server {

class ChangeOrder {
 public:
  static constexpr size_t kMaxWaiting = 10000;  // changes waiting for a resync; past it they are dropped

  // What an arriving change asks of the relay.
  struct Arrival {
    std::optional<BrokerEvent> apply;  // apply this now
    bool resync = false;               // read the session whole (call resync_started() as it goes out)
    size_t dropped = 0;                // changes that waited, dropped for the overflow (the resync brings them)
  };
  Arrival arrive(BrokerEvent event);

  // A resync went out; or it could not go out or its session is gone (no broker now: its
  // reconnection resyncs every session).
  void resync_started() { syncing_ = true; }
  void resync_abandoned() { syncing_ = false; }
  // The broker went away: what waited is dropped, since the reconnection reads every session whole.
  void broker_lost();

  // The resync read the session at `revision`: the changes that waited and follow it, in order,
  // to apply now; and whether a gap among them asks for another resync (those behind it wait for
  // that one).
  struct Resynced {
    std::vector<BrokerEvent> apply;
    bool resync = false;
  };
  Resynced resynced(uint32_t revision);

  uint32_t revision() const { return revision_; }  // the broker's revision applied here
  bool syncing() const { return syncing_; }

 private:
  size_t wait(BrokerEvent event);  // how many it dropped to make room
  uint32_t revision_ = 0;
  bool syncing_ = false;
  std::vector<BrokerEvent> waiting_;
};

}  // namespace inkwire::server
