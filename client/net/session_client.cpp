#include "client/net/session_client.hpp"

#include <cstdio>

#include "common/error.hpp"
#include "protocol/face_versions.hpp"

namespace inkwire {
namespace {

using namespace protocol;
constexpr auto kReplyTimeout = std::chrono::seconds(10);

}  // namespace

namespace {

ByteStream plain_or_tls(asio::io_context& io, asio::ssl::context* tls) {
  return tls ? ByteStream(asio::ip::tcp::socket(io), *tls) : ByteStream(asio::ip::tcp::socket(io));
}

}  // namespace

SessionClient::SessionClient(const std::string& host_port, const std::string& client_name, std::shared_ptr<asio::ssl::context> tls)
    : tls_(std::move(tls)), stream_(plain_or_tls(io_, tls_.get())), client_name_(client_name.substr(0, kMaxName)) {
  const size_t colon = host_port.rfind(':');
  if (colon == std::string::npos || colon == 0) throw Error("--connect '" + host_port + "' is not HOST:PORT");
  const std::string host = host_ = host_port.substr(0, colon);
  std::error_code ec;
  asio::ip::tcp::resolver resolver(io_);
  endpoints_ = resolver.resolve(host, host_port.substr(colon + 1), ec);
  if (!ec) asio::connect(stream_.socket(), endpoints_, ec);
  if (ec) throw Error("cannot connect to " + host_port + ": " + ec.message());
  stream_.socket().set_option(asio::ip::tcp::no_delay(true), ec);
  if (auto* tls_stream = stream_.tls_stream()) {
    // The name the certificate must carry, and the one the server is asked for (SNI).
    tls_stream->set_verify_callback(asio::ssl::host_name_verification(host));
    SSL_set_tlsext_host_name(tls_stream->native_handle(), host.c_str());
    tls_stream->handshake(asio::ssl::stream_base::client, ec);
    if (ec) throw Error("TLS with " + host_port + " failed: " + ec.message());
  }
  start_reading();
  watch_for_silence();
  thread_ = std::thread([this] { io_.run(); });
  try {
    send(Hello{.client_name = client_name_});
    const Message reply = wait_for([](const Message& m) { return std::holds_alternative<Welcome>(m); }, kReplyTimeout);
    if (const auto* error = std::get_if<ErrorMessage>(&reply)) throw Error("server refused the connection: " + error->reason);
  } catch (const Error& e) {
    stop();  // no destructor runs for an object whose constructor threw
    // A TLS listener drops a plain client without a word: say what to try.
    if (!tls_ && std::string(e.what()).starts_with("connection closed"))
      throw Error(std::string(e.what()) + " before the server's welcome (if it speaks TLS, connect with --tls)");
    throw;
  } catch (...) {
    stop();  // no destructor runs for an object whose constructor threw
    throw;
  }
}

SessionClient::~SessionClient() { stop(); }

void SessionClient::stop() {
  stopping_ = true;
  asio::post(io_, [this] {
    silence_timer_.cancel();
    rejoin_timer_.cancel();
    stream_.close();
  });
  if (thread_.joinable()) thread_.join();
}

void SessionClient::drop_connection() {
  asio::post(io_, [this] { stream_.close(); });
}

void SessionClient::lost(const std::string& reason) {
  silence_timer_.cancel();
  const bool again = rejoin_ && !stopping_ && !session_.empty();
  {
    std::lock_guard lock(mutex_);
    if (!connected_) return;  // already lost (the socket closed after the silence): the first reason stands
    rejoining_ = again;       // before connected_ turns false, so no reader sees the client as over
    connected_ = false;
    if (!reason.empty()) last_error_ = reason;
    changed_.notify_all();
  }
  stream_.close();  // a write in flight ends with an error and empties the outbox
  if (!again) return;
  rejoin_until_ = std::chrono::steady_clock::now() + kRejoinFor;
  std::fprintf(stderr, "inkwire-client: the connection was lost%s: joining again\n", reason.empty() ? "" : (" (" + reason + ")").c_str());
  rejoin_later();
}

void SessionClient::rejoin_later() {
  if (stopping_ || std::chrono::steady_clock::now() > rejoin_until_) {
    rejoining_ = false;
    std::lock_guard lock(mutex_);
    changed_.notify_all();
    return;
  }
  rejoin_timer_.expires_after(kRejoinEvery);
  rejoin_timer_.async_wait([this](std::error_code ec) {
    if (ec || stopping_) return;
    stream_ = plain_or_tls(io_, tls_.get());
    asio::async_connect(stream_.socket(), endpoints_, [this](std::error_code ec, const asio::ip::tcp::endpoint&) {
      if (ec) return rejoin_later();
      stream_.socket().set_option(asio::ip::tcp::no_delay(true), ec);
      auto* tls_stream = stream_.tls_stream();
      if (!tls_stream) return rejoined();
      tls_stream->set_verify_callback(asio::ssl::host_name_verification(host_));
      SSL_set_tlsext_host_name(tls_stream->native_handle(), host_.c_str());
      tls_stream->async_handshake(asio::ssl::stream_base::client, [this](std::error_code ec) { ec ? rejoin_later() : rejoined(); });
    });
  });
}

void SessionClient::rejoined() {
  decoder_ = FrameDecoder();
  last_heard_ = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(mutex_);
    connected_ = true;
    last_error_.clear();
    replies_.clear();
  }
  // Hello and join ahead of anything sent meanwhile (dropped while not connected).
  outbox_.clear();
  for (const Message& m : {Message(Hello{.client_name = client_name_}), Message(Join{.session = session_, .token = token_, .open_room = open_room_})}) {
    outbox_.push_back(encode(m));
    bytes_sent_ += outbox_.back().size();
  }
  ++connections_;
  rejoining_ = false;
  std::fprintf(stderr, "inkwire-client: connected again, joining '%s'\n", session_.c_str());
  start_reading();
  watch_for_silence();
  write_next();
}

void SessionClient::watch_for_silence() {
  silence_timer_.expires_after(std::chrono::seconds(1));
  silence_timer_.async_wait([this](std::error_code ec) {
    if (ec) return;
    if (std::chrono::steady_clock::now() - last_heard_ <= kServerSilence) return watch_for_silence();
    lost("no word from the server for " + std::to_string(kServerSilence.count()) + " seconds");
  });
}

void SessionClient::start_reading() {
  stream_.async_read_some(asio::buffer(read_buffer_), [this, connection = connections_.load()](std::error_code ec, size_t n) {
    if (connection != connections_) return;  // a read of an earlier connection (rejoin)
    if (ec) {
      if (ec == asio::error::operation_aborted && stopping_) return;
      lost(ec == asio::error::eof || ec == asio::error::operation_aborted ? "" : ec.message());
      return;
    }
    bytes_received_ += n;
    last_heard_ = std::chrono::steady_clock::now();
    try {
      decoder_.feed(read_buffer_.data(), n);
      while (auto m = decoder_.next()) on_message(std::move(*m));
    } catch (const ProtocolError& e) {
      lost(std::string("malformed data from the server: ") + e.what());
      return;
    }
    start_reading();
  });
}

void SessionClient::on_message(Message message) {
  if (const auto* ping = std::get_if<Ping>(&message)) {
    send(Pong{.nonce = ping->nonce});
    return;
  }
  std::lock_guard lock(mutex_);
  if (const auto* snapshot = std::get_if<Snapshot>(&message)) {
    state_ = *snapshot;
    tween_cells_.clear();  // the product's cells follow the snapshot
    ++updates_;
    replies_.push_back(std::move(message));
  } else if (auto* cell = std::get_if<TweenData>(&message)) {
    // Checked against the product when it is decoded; here only kept (a cell index past the
    // product's is ignored, a repeated one replaces).
    if (cell->pair < state_.product.cells) {
      tween_cells_[cell->pair] = std::move(cell->data);
      ++updates_;
    }
  } else if (apply_state_change(state_, message)) {
    ++updates_;
  } else if (auto* roster = std::get_if<Roster>(&message)) {
    roster_ = std::move(*roster);
    ++updates_;
  } else if (auto* permissions = std::get_if<Permissions>(&message)) {
    permissions_ = std::move(*permissions);
    ++updates_;
  } else if (std::holds_alternative<MemberLayers>(message) || std::holds_alternative<MemberFace>(message)) {
    const MemberLayers face = std::holds_alternative<MemberLayers>(message) ? std::get<MemberLayers>(message) : member_layers_of(std::get<MemberFace>(message));
    member_faces_[face.member] = face;
    if (face_queue_.size() >= 1000) face_queue_.pop_front();
    face_queue_.push_back(face);
    ++updates_;
  } else if (const auto* region = std::get_if<FaceRegion>(&message)) {
    face_region_ = *region;
  } else if (std::holds_alternative<KeyFrameRequest>(message)) {
    key_frame_requested_ = true;
  } else if (auto* voice = std::get_if<VoiceFrame>(&message)) {
    constexpr size_t kKept = 500;  // ten seconds of 20 ms packets
    if (voice_.size() >= kKept) voice_.pop_front();
    voice_.push_back({std::move(*voice), std::chrono::steady_clock::now()});
  } else if (const auto* refused = std::get_if<ErrorMessage>(&message); refused && refused->code == ErrorCode::NotAllowed) {
    // A change this member may not make: the session's own value follows it; nothing else stops.
    refusal_ = refused->reason;
    ++refusals_;
    std::fprintf(stderr, "inkwire-client: change refused: %s\n", refused->reason.c_str());
  } else if (const auto* key = std::get_if<HostKey>(&message)) {
    // This client opened the room: it joins again with the key, so it is its host again.
    token_ = key->key;
    host_key_ = key->key;
    std::fprintf(stderr, "inkwire-client: you opened room '%s' and are its host\n", session_.c_str());
  } else if (const auto* error = std::get_if<ErrorMessage>(&message)) {
    // A locked room or the host's removal: not joined again by itself.
    if (error->code == ErrorCode::Locked || error->code == ErrorCode::Removed) rejoin_ = false;
    last_error_ = error->reason;
    std::fprintf(stderr, "inkwire-client: server says: %s\n", error->reason.c_str());
    replies_.push_back(std::move(message));
  } else if (std::holds_alternative<Welcome>(message) || std::holds_alternative<AssetChunk>(message)) {
    replies_.push_back(std::move(message));
  }
  changed_.notify_all();
}

void SessionClient::send(const Message& message) {
  {
    std::lock_guard lock(mutex_);
    if (apply_state_change(state_, message)) ++updates_, changed_.notify_all();
  }
  {
    std::lock_guard lock(mutex_);
    if (!connected_ && rejoin_) return;  // between connections: a rejoin says hello and join first
  }
  auto frame = std::make_shared<Bytes>(encode(message));
  bytes_sent_ += frame->size();
  asio::post(io_, [this, frame] {
    outbox_.push_back(std::move(*frame));
    if (!writing_) write_next();
  });
}

void SessionClient::write_next() {
  if (outbox_.empty()) {
    writing_ = false;
    return;
  }
  writing_ = true;
  // A write of an earlier connection (rejoin) that ends late owns nothing of this one's outbox.
  asio::async_write(stream_, asio::buffer(outbox_.front()), [this, connection = connections_.load()](std::error_code ec, size_t) {
    if (connection != connections_) return;
    if (ec) {
      outbox_.clear();  // the connection is gone: lost() says so, a rejoin starts a new outbox
      writing_ = false;
      return;
    }
    outbox_.pop_front();
    write_next();
  });
}

Message SessionClient::wait_for(std::function<bool(const Message&)> wanted, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    for (auto it = replies_.begin(); it != replies_.end(); ++it) {
      if (wanted(*it) || std::holds_alternative<ErrorMessage>(*it)) {
        Message m = std::move(*it);
        replies_.erase(it);
        return m;
      }
    }
    if (!connected_) throw Error("connection closed" + (last_error_.empty() ? std::string() : ": " + last_error_));
    if (changed_.wait_until(lock, deadline) == std::cv_status::timeout) throw Error("no answer from the server in time");
  }
}

Snapshot SessionClient::join(const std::string& session, const std::string& token, bool open_room) {
  {
    std::lock_guard lock(mutex_);
    session_ = session, token_ = token, open_room_ = open_room;  // what a rejoin joins
  }
  send(Join{.session = session, .token = token, .open_room = open_room});
  const Message reply = wait_for([](const Message& m) { return std::holds_alternative<Snapshot>(m); }, kReplyTimeout);
  if (const auto* error = std::get_if<ErrorMessage>(&reply)) throw Error("cannot join '" + session + "': " + error->reason);
  return std::get<Snapshot>(reply);
}

Snapshot SessionClient::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

uint64_t SessionClient::updates() const {
  std::lock_guard lock(mutex_);
  return updates_;
}

uint64_t SessionClient::wait_for_update(uint64_t seen, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return updates_ > seen || !connected_; });
  return updates_;
}

bool SessionClient::connected() const {
  std::lock_guard lock(mutex_);
  return connected_;
}

Permissions SessionClient::permissions() const {
  std::lock_guard lock(mutex_);
  return permissions_;
}

Roster SessionClient::roster() const {
  std::lock_guard lock(mutex_);
  return roster_;
}

std::map<uint16_t, MemberLayers> SessionClient::member_faces() const {
  std::lock_guard lock(mutex_);
  return member_faces_;
}

std::optional<FaceRegion> SessionClient::face_region() const {
  std::lock_guard lock(mutex_);
  return face_region_;
}

std::deque<MemberLayers> SessionClient::take_member_faces() {
  std::lock_guard lock(mutex_);
  return std::exchange(face_queue_, {});
}

std::deque<SessionClient::ReceivedVoice> SessionClient::take_voice() {
  std::lock_guard lock(mutex_);
  return std::exchange(voice_, {});
}

std::string SessionClient::refusal() const {
  std::lock_guard lock(mutex_);
  return refusal_;
}

uint64_t SessionClient::refusals() const {
  std::lock_guard lock(mutex_);
  return refusals_;
}

std::string SessionClient::last_error() const {
  std::lock_guard lock(mutex_);
  return last_error_;
}

std::map<uint16_t, Bytes> SessionClient::tween_cells() const {
  std::lock_guard lock(mutex_);
  return tween_cells_;
}

std::vector<std::filesystem::path> SessionClient::fetch_assets(const Snapshot& snapshot, AssetCache& cache) {
  std::vector<std::filesystem::path> paths;
  for (const AssetAnnounce& asset : snapshot.assets) paths.push_back(fetch_asset(asset, cache));
  return paths;
}

std::filesystem::path SessionClient::fetch_asset(const AssetAnnounce& asset, AssetCache& cache) {
  // Alone with the asset's file: another download of it (a thread here, another process) ends first.
  std::optional<AssetCache::Download> download = cache.begin(asset);
  if (!download) return cache.path_of(asset);
  uint64_t received = download->resume_at(), requested = received;
  while (received < asset.size) {
    // Keep a few requests in flight so a download is not one round trip per chunk.
    while (requested < asset.size && requested - received < kRequestsAhead * kMaxChunk) {
      const auto length = uint32_t(std::min<uint64_t>(kMaxChunk, asset.size - requested));
      send(AssetRequest{.hash = asset.hash, .offset = requested, .length = length});
      requested += length;
    }
    const Message reply = wait_for([&](const Message& m) {
      const auto* chunk = std::get_if<AssetChunk>(&m);
      return chunk && chunk->hash == asset.hash;
    }, kReplyTimeout);
    if (const auto* error = std::get_if<ErrorMessage>(&reply)) throw Error("cannot fetch " + asset.name + ": " + error->reason);
    const auto& chunk = std::get<AssetChunk>(reply);
    if (chunk.data.empty()) throw Error("server sent an empty chunk of " + asset.name);
    download->append(chunk.offset, chunk.data);
    received += chunk.data.size();
  }
  return download->finish();
}

}  // namespace inkwire
