#pragma once
// What the instances write into the broker and read back (docs/deploy.md "What the broker
// holds"): a change as published, and a session's definition. Names are counted
// ("LENGTH:BYTES") so they may hold any character; the protocol frames inside are the wire's own.
// What comes back is read as untrusted input: every length is checked against what is left
// (tests/fuzz/fuzz_broker.cpp).
#include <cstdint>
#include <string>
#include <optional>
#include <string_view>

#include "protocol/messages.hpp"
#include "server/stored_session.hpp"

namespace inkwire::server {

// A change as every instance receives it from the broker.
struct BrokerEvent {
  uint32_t revision = 0;     // the session's count of changes, given by the broker
  int64_t published_us = 0;  // when the publishing instance sent it (its clock)
  uint64_t sender = 0;       // the member's connection id on that instance (0: the server)
  std::string origin, session;
  protocol::Message change;  // a style, camera, object pose or expression
};

// The part of a published change the instance writes: "TIME SENDER ORIGIN SESSION" (the
// broker's script puts "REVISION " before it and the change's frame after it).
std::string event_header(int64_t published_us, uint64_t sender, const std::string& origin, const std::string& session);
// The whole published text back. Throws protocol::ProtocolError naming what is wrong.
BrokerEvent parse_event(std::string_view payload);

// A session's definition as instances share it: its tokens' digests and its state as a snapshot.
std::string session_definition(const StoredSession& stored);
// Throws protocol::ProtocolError naming what is wrong.
StoredSession parse_session_definition(std::string_view text);

// A call's traffic between instances (SPEC F12): what an instance's own members publish, for
// the members on other instances. `message` is a voice-frame or member-layers (member-face from
// an instance of version 7 or 8) of one of the origin's members (by the origin's member number),
// or a roster of the origin's own members (its `host` the origin's number of the room's host
// when the host is there, and then its `locked` the room's); a member's neutral photo travels
// with its landmarks' JSON (photo_member non-zero). A room's host removing a member of another
// instance asks that instance to (`removal`: the instance, its number for the member, the reason
// the member is given).
struct CallShare {
  struct Removal {
    std::string instance;
    uint16_t member = 0;
    std::string reason;
    bool operator==(const Removal&) const = default;
  };
  std::string origin, session;
  std::optional<protocol::Message> message;
  uint16_t photo_member = 0;
  protocol::Bytes photo;
  std::string landmarks;
  std::optional<Removal> removal;
};
std::string call_share(const CallShare& share);
// Throws protocol::ProtocolError naming what is wrong.
CallShare parse_call_share(std::string_view text);

// Which field of a session's state `change` is ("style", "camera", "object", "expression").
// Throws protocol::ProtocolError for a message that is no session state.
std::string state_field(const protocol::Message& change);

}  // namespace inkwire::server
