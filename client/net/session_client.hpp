#pragma once
// A thin client's connection to a server (SPEC N3-N5): handshake, join, the session's state as
// it changes, changes sent by this client, and assets fetched into the cache. Network I/O runs
// on its own thread; the methods here are thread-safe and meant for the render thread.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <asio.hpp>

#include "client/net/asset_cache.hpp"
#include "protocol/net/byte_stream.hpp"
#include "protocol/framing.hpp"

namespace inkwire {

class SessionClient {
 public:
  // A server pings a quiet client every few seconds (SPEC D7, at most 5 s): this long with no
  // word from it and the connection is taken as dead (connected() turns false with the reason).
  static constexpr std::chrono::seconds kServerSilence{15};
  // Asset chunks asked for at once (protocol/SPEC.md: at most 4 outstanding).
  static constexpr int kRequestsAhead = 4;

  // Connects to HOST:PORT (over TLS when `tls` is given: the server's certificate must be
  // trusted by it and name HOST) and completes the handshake; throws inkwire::Error with the
  // server's reason (e.g. a version mismatch), TLS's or the socket's.
  SessionClient(const std::string& host_port, const std::string& client_name, std::shared_ptr<asio::ssl::context> tls = nullptr);
  ~SessionClient();
  SessionClient(const SessionClient&) = delete;
  SessionClient& operator=(const SessionClient&) = delete;

  // Joins a session and waits for its snapshot; throws inkwire::Error (wrong token, no such
  // session, timeout).
  // `open_room`: open a call room of that name when no session has it (this client is then its
  // host, host_key() its key).
  protocol::Snapshot join(const std::string& session, const std::string& token, bool open_room = false);
  std::string host_key() const {
    std::lock_guard lock(mutex_);
    return host_key_;
  }
  // Sends a message; state messages are also applied to this client's own copy of the state.
  void send(const protocol::Message& message);

  // The session's current state and how many changes have arrived so far.
  protocol::Snapshot state() const;
  uint64_t updates() const;
  // Waits until more than `seen` updates have arrived or the timeout passes; returns updates().
  uint64_t wait_for_update(uint64_t seen, std::chrono::milliseconds timeout) const;
  bool connected() const;
  std::string last_error() const;

  // Rejoining (SPEC F19): once joined, a lost connection (a dropped socket, a server silent for
  // kServerSilence) is made again every kRejoinEvery for kRejoinFor, under the same name, and the
  // session joined again; connected() is false meanwhile and what is sent then is dropped.
  // `connections()` counts the connections made (1, then one more per rejoin): a publisher
  // says again what it publishes when it changes.
  static constexpr std::chrono::seconds kRejoinEvery{2}, kRejoinFor{60};
  void set_rejoin(bool rejoin) { rejoin_ = rejoin; }
  uint64_t connections() const { return connections_; }
  bool rejoining() const { return rejoining_; }  // lost, and trying again
  // Closes the socket under the client, as a dropped network would (tests).
  void drop_connection();
  // The reason the server gave for the latest change it refused (SPEC W8: this member may not
  // make it), and how many it refused so far; the session's value replaced the change.
  std::string refusal() const;
  uint64_t refusals() const;

  // Downloads every asset of the snapshot that the cache lacks (resuming partial files) and
  // returns the cached paths in the snapshot's order. Throws inkwire::Error.
  std::vector<std::filesystem::path> fetch_assets(const protocol::Snapshot& snapshot, AssetCache& cache);
  // One asset: from the cache, or downloaded into it (resuming a partial file). Throws inkwire::Error.
  std::filesystem::path fetch_asset(const protocol::AssetAnnounce& asset, AssetCache& cache);

  // The changes this member will be refused in its session, with the server's reasons (sent on
  // joining, SPEC W8): what a window turns off.
  protocol::Permissions permissions() const;

  // The tween-data messages of a turntable session's product received since the last
  // snapshot (SPEC T12), by cell index, and how many have arrived.
  std::map<uint16_t, protocol::Bytes> tween_cells() const;

  // Calls (SPEC F7-F12): the newest roster, each member's newest face, where the server last
  // found this member's face, and the voice packets received since the last take (at most a
  // few seconds' worth are kept: a reader that does not take them loses the oldest).
  protocol::Roster roster() const;
  // Faces come as member-layers (a member-face from a server of version 7 or 8 is read as layers).
  std::map<uint16_t, protocol::MemberLayers> member_faces() const;
  std::optional<protocol::FaceRegion> face_region() const;
  // True once after the server asked for a key frame of this member's face video.
  bool take_key_frame_request() { return key_frame_requested_.exchange(false); }
  struct ReceivedVoice {
    protocol::VoiceFrame frame;
    std::chrono::steady_clock::time_point arrived;
  };
  std::deque<ReceivedVoice> take_voice();
  // Every member-face received since the last take, in order (a few seconds' worth at most).
  std::deque<protocol::MemberLayers> take_member_faces();

  uint64_t bytes_sent() const { return bytes_sent_; }
  uint64_t bytes_received() const { return bytes_received_; }

 private:
  void stop();  // closes the socket and ends the I/O thread
  void start_reading();
  void watch_for_silence();  // on the I/O thread: a server silent for kServerSilence is taken as gone
  // On the I/O thread: the connection is gone (the reason for last_error, empty for none).
  void lost(const std::string& reason);
  void rejoin_later();  // on the I/O thread: the next attempt, while kRejoinFor lasts
  void rejoined();      // on the I/O thread: connected again: hello and join go first
  void on_message(protocol::Message message);
  void write_next();
  protocol::Message wait_for(std::function<bool(const protocol::Message&)> wanted, std::chrono::milliseconds timeout);

  asio::io_context io_;
  std::shared_ptr<asio::ssl::context> tls_;
  ByteStream stream_;
  std::thread thread_;
  std::array<uint8_t, 16384> read_buffer_{};
  protocol::FrameDecoder decoder_;
  std::deque<protocol::Bytes> outbox_;  // touched on the I/O thread only
  bool writing_ = false;
  asio::steady_timer silence_timer_{io_};
  asio::steady_timer rejoin_timer_{io_};
  asio::ip::tcp::resolver::results_type endpoints_;
  std::string host_, client_name_, session_, token_;  // what a rejoin says again
  bool open_room_ = false;
  std::string host_key_;
  std::chrono::steady_clock::time_point rejoin_until_{};  // I/O thread only
  std::atomic<bool> rejoin_{false}, rejoining_{false}, stopping_{false};
  std::atomic<uint64_t> connections_{1};
  std::chrono::steady_clock::time_point last_heard_ = std::chrono::steady_clock::now();  // I/O thread only

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  protocol::Snapshot state_;
  std::map<uint16_t, protocol::Bytes> tween_cells_;
  protocol::Roster roster_;
  protocol::Permissions permissions_;
  std::map<uint16_t, protocol::MemberLayers> member_faces_;
  std::optional<protocol::FaceRegion> face_region_;
  std::atomic<bool> key_frame_requested_{false};
  std::deque<ReceivedVoice> voice_;
  std::deque<protocol::MemberLayers> face_queue_;
  uint64_t updates_ = 0;
  bool connected_ = true;
  std::string last_error_, refusal_;
  uint64_t refusals_ = 0;
  std::deque<protocol::Message> replies_;  // welcome, snapshot, errors, asset chunks, awaited by callers
  std::atomic<uint64_t> bytes_sent_{0}, bytes_received_{0};
};

}  // namespace inkwire
