#include "server/connection.hpp"

#include <asio/experimental/as_tuple.hpp>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "protocol/versions.hpp"
#include "server/making/session_maker.hpp"
#include "server/relay/relay.hpp"
#include "server/server.hpp"
#include "server/session.hpp"
#include "server/session_token.hpp"
#include "server/web/voice_stream.hpp"

namespace inkwire::server {
namespace {

using namespace protocol;
constexpr auto no_throw = asio::experimental::as_tuple(asio::use_awaitable);

}  // namespace

Connection::Connection(std::unique_ptr<Transport> transport, Server& server, uint64_t id)
    : transport_(std::move(transport)),
      wake_(transport_->executor(), asio::steady_timer::time_point::max()),
      server_(server),
      id_(id),
      peer_(transport_->peer()),
      address_(peer_.substr(0, peer_.rfind(':'))),
      queue_(server.config().queue_bytes) {}

void Connection::start() {
  auto self = shared_from_this();
  asio::co_spawn(transport_->executor(), [self] { return self->read_loop(); }, asio::detached);
  asio::co_spawn(transport_->executor(), [self] { return self->write_loop(); }, asio::detached);
  asio::co_spawn(transport_->executor(), [self] { return self->watchdog(); }, asio::detached);
}

void Connection::send(const Message& message) {
  send_frame(std::make_shared<const Bytes>(encode(message)), type_of(message));
}

void Connection::send_frame(std::shared_ptr<const Bytes> frame, MessageType type) {
  if (closing_) return;
  // An older peer is sent its version's frame; a type newer than it would end its connection, so
  // it is not sent (callers such as Call::send_face send what it reads instead).
  frame = frame_for(version_, std::move(frame), type);
  if (!frame) return;
  if (type == MessageType::VoiceFrame && voice_stream_) {
    if (voice_stream_->open()) {
      voice_stream_->send(std::move(frame));
      return;
    }
    voice_stream_.reset();  // ended: voice comes this way again
  }
  const uint64_t replaced = queue_.replaced();
  if (!queue_.push(std::move(frame), type)) {
    ++server_.counters().too_slow;
    log_warn("too-slow", {{"client", id_}, {"queued_bytes", queue_.bytes()}});
    close_with(ErrorCode::TooSlow, "send queue overflowed: the client is not reading");
    return;
  }
  server_.counters().replaced += queue_.replaced() - replaced;
  wake_.cancel();
}

void Connection::close_with(ErrorCode code, const std::string& reason) {
  if (closing_) return;
  // The error goes out even past the byte limit: it is the last thing this peer gets.
  queue_.take_all();
  queue_.push(frame_for(version_, std::make_shared<const Bytes>(encode(ErrorMessage{.code = code, .reason = reason.substr(0, kMaxReason)})),
                       MessageType::Error),
              MessageType::Error);
  closing_ = true;
  closed_for_ = {code, reason};
  wake_.cancel();
  // A peer that does not read would keep the error unsent forever: cut it off after a few
  // seconds. (One was too few: a browser on a loaded machine, still taking the batch written
  // before the error, lost the host's "removed you", joined again and was told the room is locked.)
  auto self = shared_from_this();
  auto timer = std::make_shared<asio::steady_timer>(transport_->executor(), std::chrono::seconds(5));
  timer->async_wait([self, timer](std::error_code) { self->shut(); });
}

void Connection::shut() {
  if (shut_) return;
  shut_ = true;
  closing_ = true;
  leave_session();
  transport_->close();
  wake_.cancel();
  server_.forget(this);
}

asio::awaitable<void> Connection::watchdog() {
  const auto seconds = [](double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); };
  const ServerConfig& config = server_.config();
  const auto hello = seconds(config.hello_timeout_seconds), idle = seconds(config.idle_timeout_seconds), beat = seconds(config.heartbeat_seconds);
  // Checked a few times per heartbeat: a deadline is met within a quarter of a beat.
  asio::steady_timer timer(transport_->executor());
  const Clock::time_point opened = Clock::now();
  auto self = shared_from_this();
  while (!closing_ && !shut_) {
    timer.expires_after(std::min(beat, hello) / 4);
    co_await timer.async_wait(no_throw);
    if (closing_ || shut_) break;
    const Clock::time_point now = Clock::now();
    if (!greeted_) {
      if (now - opened > hello) close_with(ErrorCode::Malformed, "no hello within " + std::to_string(int(config.hello_timeout_seconds)) + " seconds");
      continue;
    }
    if (writing_since_ && now - *writing_since_ > idle) {
      ++server_.counters().idle_closed;
      log_warn("not-reading", {{"client", id_}, {"name", client_name_}, {"seconds", config.idle_timeout_seconds}});
      // The peer takes nothing: the error could not reach it either.
      shut();
    } else if (now - last_heard_ > idle) {
      ++server_.counters().idle_closed;
      log_warn("idle-timeout", {{"client", id_}, {"name", client_name_}, {"seconds", config.idle_timeout_seconds}});
      close_with(ErrorCode::Refused, "nothing heard for " + std::to_string(int(config.idle_timeout_seconds)) + " seconds: closed as gone");
    } else if ((now - last_heard_ > beat || now - last_written_ > beat) && now - last_ping_ > beat) {
      // A quiet peer is pinged, and so is one that talks but is sent nothing (a member steering
      // a session nobody else changes): a client takes a server it has not heard from for a
      // while as gone (SessionClient::kServerSilence), whatever it sends itself.
      last_ping_ = now;
      send(Ping{.nonce = ++pings_sent_});
    }
  }
}

asio::awaitable<void> Connection::read_loop() {
  auto self = shared_from_this();  // keeps the connection alive while reading
  Bytes frame;
  while (!closing_) {
    try {
      if (const std::error_code ec = co_await transport_->read_frame(frame)) break;
      last_heard_ = Clock::now();
      const FrameHeader h = parse_header(frame.data());
      Message message = decode_from(version_, h.type, frame.data() + kHeaderBytes, frame.size() - kHeaderBytes);
      ++server_.counters().messages_in;
      // An address that guessed tokens waits before each join is looked at (this connection
      // reads nothing meanwhile; the others are served as usual).
      if (h.type == MessageType::Join)
        if (const auto delay = server_.admission().join_delay(address_); delay.count() > 0) {
          log_info("join-slowed", {{"client", id_}, {"peer", peer_}, {"delay_ms", delay.count()}});
          asio::steady_timer pause(transport_->executor(), delay);
          co_await pause.async_wait(no_throw);
          if (closing_) break;
        }
      handle(message);
    } catch (const ProtocolError& e) {
      log_warn("malformed", {{"client", id_}, {"peer", peer_}, {"transport", transport_->name()}, {"reason", e.what()}});
      close_with(ErrorCode::Malformed, e.what());
    } catch (const std::exception& e) {
      log(LogLevel::Error, "internal", {{"client", id_}, {"reason", e.what()}});
      close_with(ErrorCode::Refused, e.what());
    }
  }
  if (!closing_) {
    log_info("disconnect", {{"client", id_}, {"name", client_name_}});
    shut();
  }
}

asio::awaitable<void> Connection::write_loop() {
  auto self = shared_from_this();
  while (!shut_) {
    if (queue_.empty()) {
      if (closing_) break;
      wake_.expires_at(asio::steady_timer::time_point::max());
      co_await wake_.async_wait(no_throw);
      continue;
    }
    // Everything queued goes out in one gathered write.
    const std::deque<Outgoing> batch = queue_.take_all();
    writing_since_ = last_written_ = Clock::now();
    const std::error_code failed = co_await transport_->write_frames(batch);
    writing_since_.reset();
    if (failed) break;
    server_.counters().messages_out += batch.size();
  }
  if (closing_ && !shut_) co_await transport_->goodbye(closed_for_.first, closed_for_.second);
  shut();
}

void Connection::handle(Message& message) {
  if (!greeted_) {
    const auto* hello = std::get_if<Hello>(&message);
    if (!hello) throw ProtocolError(std::string("expected hello, got ") + name_of(type_of(message)));
    if (hello->magic != kMagic || hello->version < kOldestVersion || hello->version > kVersion) {
      log_warn("bad-version", {{"client", id_}, {"peer", peer_}, {"version", hello->version}});
      close_with(ErrorCode::BadVersion, "protocol mismatch: server speaks Inkwire version " + std::to_string(kVersion) + " (and back to " +
                                            std::to_string(kOldestVersion) + "), client sent magic " + std::to_string(hello->magic) + " version " +
                                            std::to_string(hello->version));
      return;
    }
    greeted_ = true;
    version_ = hello->version;
    client_name_ = hello->client_name;
    log_info("hello", {{"client", id_}, {"peer", peer_}, {"name", client_name_}});
    send(Welcome{.version = version_, .server_name = server_.config().name});  // the version it is spoken to in
    return;
  }
  switch (type_of(message)) {
    case MessageType::Ping: send(Pong{.nonce = std::get<Ping>(message).nonce}); break;
    case MessageType::Pong: break;
    case MessageType::Join: join(std::get<Join>(message)); break;
    case MessageType::Leave: leave_session(); break;
    case MessageType::AssetRequest: serve_asset(std::get<AssetRequest>(message)); break;
    case MessageType::Error:
      log_info("client-error", {{"client", id_}, {"reason", std::get<ErrorMessage>(message).reason}});
      break;
    case MessageType::Publish:
    case MessageType::NeutralPhoto:
    case MessageType::FaceCrop:
    case MessageType::FaceVideo:
    case MessageType::VoiceFrame:
      publish(message);
      break;
    case MessageType::RoomControl: control_room(std::get<RoomControl>(message)); break;
    case MessageType::StyleChange:
    case MessageType::CameraPose:
    case MessageType::ObjectPose:
    case MessageType::ExpressionCode:
      change(message);
      break;
    default:
      throw ProtocolError(std::string("a client may not send ") + name_of(type_of(message)));
  }
}

void Connection::join(const Join& join) {
  std::shared_ptr<Session> session = server_.find_session(join.session);
  std::string host_key;
  if (!session && join.open_room) {
    // A call room of that name, opened for this member, who becomes its host (SPEC N6-N7).
    SessionMaker::Made made = server_.maker().open_room(join.session, join.token, address_, SessionMaker::Clock::now());
    if (!made.session) {
      log_info("room-refused", {{"client", id_}, {"peer", peer_}, {"session", join.session}, {"reason", made.refusal}});
      send(ErrorMessage{.code = ErrorCode::Refused, .reason = made.refusal});
      return;
    }
    session = std::move(made.session);
    host_key = std::move(made.key);
  }
  if (!session) {
    send(ErrorMessage{.code = ErrorCode::NoSession, .reason = "no session named '" + join.session + "'"});
    return;
  }
  std::optional<Role> role = host_key.empty() ? session->role_of(join.token) : std::optional<Role>(Role::Editor);
  // Asking to open a room that is open already joins it: the token given (a creator token, or a
  // host key of a room of that name that is gone) is no guess at this one's key.
  if (!role && join.open_room) role = session->role_of("");
  if (!role) {
    server_.admission().join_failed(address_);
    log_warn("bad-token", {{"client", id_}, {"peer", peer_}, {"session", join.session}});
    send(ErrorMessage{.code = ErrorCode::BadToken, .reason = "wrong token for session '" + join.session + "'"});
    return;
  }
  if (!session->unavailable().empty()) {
    send(ErrorMessage{.code = ErrorCode::NoAsset, .reason = "session '" + join.session + "' cannot be shown: " + session->unavailable()});
    return;
  }
  if (Call* call = session->call(); call && call->locked() && *role != Role::Editor) {
    const std::string host = call->host_name();
    send(ErrorMessage{.code = ErrorCode::Locked,
                      .reason = "room " + join.session + " is locked: ask " + (host.empty() ? std::string("its host") : host + " (its host)") + " to open it"});
    return;
  }
  if (!join.token.empty() && host_key.empty()) server_.admission().join_succeeded(address_);
  leave_session();
  session_ = session;
  role_ = *role;
  session_->join(shared_from_this());
  if (Call* call = session_->call()) call->join(shared_from_this(), client_name_, role_ == Role::Editor);
  log_info("join", {{"client", id_}, {"name", client_name_}, {"session", join.session}, {"members", session_->members()},
                    {"role", role_ == Role::Editor ? "editor" : "visitor"}});
  send(session_->state());
  if (!host_key.empty()) send(HostKey{.key = host_key});
  // What this member will be refused, said now: its controls for those can be off from the start.
  Permissions permissions;
  for (const MessageType change : {MessageType::StyleChange, MessageType::CameraPose, MessageType::ObjectPose, MessageType::ExpressionCode})
    if (std::string reason = refusal(session_->authority(), role_, change); !reason.empty())
      permissions.refused.push_back({.change = change, .reason = std::move(reason)});
  send(permissions);
  // A member on a WebSocket may hear the call on a second route, which browsers that carry a
  // worker's WebSocket on the page's thread (Firefox) keep off it.
  if (session_->call() && transport_->name().starts_with("websocket")) {
    voice_ticket_ = random_hex(protocol::kVoiceTicketChars / 2);
    send(VoiceRoute{.ticket = voice_ticket_});
  }
  cells_pending_ = !session_->tween_frames().empty();
  if (cells_pending_) {
    // A member that holds every photo already asks for none: its cells go after two seconds.
    cells_timer_ = std::make_shared<asio::steady_timer>(transport_->executor(), std::chrono::seconds(2));
    std::weak_ptr<Connection> weak = shared_from_this();
    cells_timer_->async_wait([weak](std::error_code ec) {
      if (const auto self = weak.lock(); self && !ec) self->send_tween_cells();
    });
  }
}

// What a call member publishes of itself (SPEC F7-F9): its camera and microphone, its neutral
// photo, face crops, voice. Only in a call; the call stamps it with this member's own number.
void Connection::publish(Message& message) {
  Call* call = session_ ? session_->call() : nullptr;
  if (!call) {
    send(ErrorMessage{.code = session_ ? ErrorCode::NotAllowed : ErrorCode::NotJoined,
                      .reason = std::string(name_of(type_of(message))) + (session_ ? " outside a call" : " before joining a call")});
    return;
  }
  if (auto* p = std::get_if<Publish>(&message)) call->publish(id_, *p);
  else if (auto* photo = std::get_if<NeutralPhoto>(&message)) call->photo(id_, std::move(photo->jpeg));
  else if (auto* crop = std::get_if<FaceCrop>(&message)) call->crop(id_, std::move(*crop));
  else if (auto* video = std::get_if<FaceVideo>(&message)) call->video(id_, std::move(*video));
  else if (auto* voice = std::get_if<VoiceFrame>(&message)) call->voice(id_, std::move(*voice));
}

// A state change from this member: relayed to the session when its role allows it, otherwise
// refused with the reason, and the session's own value sent back so the member, which applied
// the change to its copy already, shows what everyone else sees.
void Connection::change(const Message& change) {
  const MessageType type = type_of(change);
  if (!session_) {
    send(ErrorMessage{.code = ErrorCode::NotJoined, .reason = std::string(name_of(type)) + " before joining a session"});
    return;
  }
  if (const std::string reason = refusal(session_->authority(), role_, type); !reason.empty()) {
    ++server_.counters().changes_refused;
    log_info("change-refused", {{"client", id_}, {"session", session_->name()}, {"change", name_of(type)}});
    send(ErrorMessage{.code = ErrorCode::NotAllowed, .reason = reason});
    const Snapshot& state = session_->state();
    if (type == MessageType::StyleChange) send(state.style);
    else if (type == MessageType::CameraPose) send(state.camera);
    else if (type == MessageType::ObjectPose) send(state.object);
    else send(state.expression);
    return;
  }
  server_.relay().publish(*session_, change, id_);
}

// The host's controls of its room (SPEC N7): from anyone else, refused with the reason.
void Connection::control_room(const RoomControl& control) {
  Call* call = session_ ? session_->call() : nullptr;
  if (!call) {
    send(ErrorMessage{.code = session_ ? ErrorCode::NotAllowed : ErrorCode::NotJoined, .reason = "room-control outside a call"});
    return;
  }
  if (role_ != Role::Editor) {
    ++server_.counters().changes_refused;
    send(ErrorMessage{.code = ErrorCode::NotAllowed, .reason = "only the room's host may lock it, open it or remove a member"});
    return;
  }
  if (control.action == RoomAction::Remove) {
    if (!call->remove(control.member, "the host removed you from room " + session_->name()))
      send(ErrorMessage{.code = ErrorCode::NotAllowed, .reason = "no member " + std::to_string(control.member) + " in this call"});
    return;
  }
  call->set_locked(control.action == RoomAction::Lock);
}

void Connection::send_tween_cells() {
  if (!cells_pending_ || !session_) return;
  cells_pending_ = false;
  if (cells_timer_) cells_timer_->cancel();
  for (const auto& frame : session_->tween_frames()) send_frame(frame, MessageType::TweenData);
}

bool Connection::holds_voice_ticket(const std::string& ticket) const {
  return !voice_ticket_.empty() && !closing_ && session_ && session_->call() && same_secret(voice_ticket_, ticket);
}

void Connection::take_voice_stream(std::shared_ptr<VoiceStream> stream) {
  voice_ticket_.clear();
  voice_stream_ = std::move(stream);
  log_info("voice-route", {{"client", id_}, {"session", session_ ? session_->name() : ""}});
}

void Connection::leave_session() {
  voice_ticket_.clear();
  if (voice_stream_) voice_stream_->close(), voice_stream_.reset();
  cells_pending_ = false;
  if (cells_timer_) cells_timer_->cancel();
  if (!session_) return;
  session_->leave(this);
  if (Call* call = session_->call()) call->leave(id_);
  log_info("leave", {{"client", id_}, {"session", session_->name()}, {"members", session_->members()}});
  session_.reset();
}

void Connection::serve_asset(const AssetRequest& request) {
  // A call member's photo and landmarks are in memory while the member is in the call.
  if (Call* call = session_ ? session_->call() : nullptr)
    if (const Bytes* bytes = call->asset(request.hash)) {
      if (request.offset > bytes->size()) {
        send(ErrorMessage{.code = ErrorCode::NoAsset, .reason = "asset " + to_hex(request.hash) + ": offset past its end"});
        return;
      }
      const size_t n = std::min<uint64_t>(request.length, bytes->size() - request.offset);
      send(AssetChunk{.hash = request.hash, .offset = request.offset, .data = Bytes(bytes->begin() + long(request.offset), bytes->begin() + long(request.offset + n))});
      return;
    }
  // Assets are served to members of a session that lists them: the token guards them too.
  const AssetAnnounce* asset = session_ ? session_->find_asset(request.hash) : nullptr;
  if (!asset) {
    send(ErrorMessage{.code = ErrorCode::NoAsset, .reason = "asset " + to_hex(request.hash) + " is not in this client's session"});
    return;
  }
  try {
    AssetChunk chunk{.hash = request.hash, .offset = request.offset, .data = server_.store().read(request.hash, request.offset, request.length)};
    const bool photo_done = cells_pending_ && asset->kind == AssetKind::Samples && request.offset + chunk.data.size() >= asset->size;
    send(chunk);
    if (photo_done) send_tween_cells();  // the member's first photo is on its way: the tween data follows it
  } catch (const Error& e) {
    send(ErrorMessage{.code = ErrorCode::NoAsset, .reason = e.what()});
  }
}

}  // namespace inkwire::server
