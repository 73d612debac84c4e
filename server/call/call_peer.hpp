#pragma once
// What a call (call.hpp) needs of a member's connection, and nothing more: who it is (its
// connection id and IP address), which protocol version it reads, how long it has been silent,
// and a way to send it a message or a frame encoded once for many, or to close it with a reason.
// The server's Connection is one; a test's own could be another, so the call's roster and intake
// run without sockets; the call never sees the rest of a connection.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "protocol/messages.hpp"

namespace inkwire::server {

class CallPeer {
 public:
  virtual ~CallPeer() = default;
  // Queues a message, or a frame encoded once for many members (a slow peer is closed, never waited for).
  virtual void send(const protocol::Message& message) = 0;
  virtual void send_frame(std::shared_ptr<const protocol::Bytes> frame, protocol::MessageType type) = 0;
  // Sends an error, then closes; the call has already let the member go or does so on leave().
  virtual void close_with(protocol::ErrorCode code, const std::string& reason) = 0;
  virtual uint64_t id() const = 0;
  // The protocol version the peer said hello with: what it can read (member-face before 9).
  virtual uint16_t version() const = 0;
  virtual const std::string& address() const = 0;  // the peer's IP address: with its name, who comes back
  // How long since anything arrived from the peer: a twin silent past two heartbeats has gone.
  virtual std::chrono::steady_clock::duration silent_for() const = 0;
};

}  // namespace inkwire::server
