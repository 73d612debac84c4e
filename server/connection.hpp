#pragma once
// One client connection (asio's pattern): a reader coroutine that decodes and handles messages, a
// writer coroutine that drains the bounded send queue, and one watchdog for every deadline: the
// hello, then silence (renewed by anything the peer sends; the server pings a quiet peer) and a
// write the peer does not take (SPEC D7). Any error ends only this connection, after telling the peer why. Frames come
// and go through a Transport (TCP or WebSocket); nothing here depends on which.
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include <asio.hpp>

#include "protocol/messages.hpp"
#include "server/authority.hpp"
#include "server/call/call_peer.hpp"
#include "server/send_queue.hpp"
#include "server/transport.hpp"

namespace inkwire::server {

class Server;
class Session;
class VoiceStream;

class Connection final : public CallPeer, public std::enable_shared_from_this<Connection> {
 public:
  Connection(std::unique_ptr<Transport> transport, Server& server, uint64_t id);

  void start();
  // Queues a message or a frame encoded once for many. A full queue closes the connection with
  // "too slow"; state messages never fill it (latest wins).
  void send(const protocol::Message& message) override;
  void send_frame(std::shared_ptr<const protocol::Bytes> frame, protocol::MessageType type) override;
  // Sends an error, then closes once it is written (or after a second if the peer is not reading).
  void close_with(protocol::ErrorCode code, const std::string& reason) override;
  uint64_t id() const override { return id_; }
  // The protocol version the peer said hello with (kOldestVersion .. kVersion): what it can read.
  uint16_t version() const override { return version_; }
  const std::string& address() const override { return address_; }  // the peer's IP address
  const Transport& transport() const { return *transport_; }
  bool in_session() const { return session_ != nullptr; }
  // How long since anything arrived from the peer (the server pings a quiet one: a live peer is
  // never silent much longer than a heartbeat).
  std::chrono::steady_clock::duration silent_for() const override { return Clock::now() - last_heard_; }
  // Whether `ticket` is the voice route this call member was sent and has not used
  // (protocol/SPEC.md "Voice route"); then take_voice_stream() makes it its route, once.
  bool holds_voice_ticket(const std::string& ticket) const;
  void take_voice_stream(std::shared_ptr<VoiceStream> stream);

 private:
  asio::awaitable<void> read_loop();
  asio::awaitable<void> write_loop();
  asio::awaitable<void> watchdog();
  void handle(protocol::Message& message);
  void join(const protocol::Join& join);
  void control_room(const protocol::RoomControl& control);
  void change(const protocol::Message& change);
  void publish(protocol::Message& message);
  void leave_session();
  void serve_asset(const protocol::AssetRequest& request);
  void send_tween_cells();
  void shut();

  std::unique_ptr<Transport> transport_;
  asio::steady_timer wake_;  // the writer sleeps on it; send() cancels it
  Server& server_;
  uint64_t id_;
  std::string peer_, address_, client_name_;
  SendQueue queue_;
  std::shared_ptr<Session> session_;
  // A product's tween data waits until the member has its first photo (or two seconds), so
  // a first view costs the snapshot and one photo.
  bool cells_pending_ = false;
  std::shared_ptr<asio::steady_timer> cells_timer_;
  Role role_ = Role::Visitor;  // in session_
  std::pair<protocol::ErrorCode, std::string> closed_for_;  // why close_with() ends the connection
  bool greeted_ = false, closing_ = false, shut_ = false;
  uint16_t version_ = protocol::kVersion;
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_heard_ = Clock::now(), last_ping_ = Clock::now(), last_written_ = Clock::now();
  std::optional<Clock::time_point> writing_since_;  // set while a write waits for the peer
  uint64_t pings_sent_ = 0;
  std::string voice_ticket_;                   // sent in voice-route, not yet used
  std::shared_ptr<VoiceStream> voice_stream_;  // where this member's voice goes while it is open
};

}  // namespace inkwire::server
