#include "server/relay/redis_relay.hpp"

#include <hiredis/hiredis.h>
#include <openssl/sha.h>

#include <algorithm>
#include <charconv>

#include "common/content_hash.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "protocol/framing.hpp"
#include "server/relay/broker_formats.hpp"
#include "server/asset_store.hpp"
#include "server/relay/session_fanout.hpp"
#include "server/session.hpp"

namespace inkwire::server {
namespace {

using namespace protocol;
using namespace std::chrono_literals;

constexpr std::string_view kEvents = "inkwire:events";      // changes, published by kPublish
constexpr std::string_view kNotices = "inkwire:notices";    // a session was shared, its model replaced, or it was removed: its name
constexpr std::string_view kCalls = "inkwire:calls";        // calls' voice, faces, rosters and photos (broker_formats.hpp)
constexpr std::string_view kSessions = "inkwire:sessions";  // hash: name -> definition
constexpr uint64_t kMaxSharedAsset = 64 << 20;              // larger assets need a shared data folder

std::string state_key(const std::string& session) { return "inkwire:state:" + session; }
std::string asset_key(const Hash& hash) { return "inkwire:asset:" + to_hex(hash); }

// Stores a change as its session's latest of its kind, counts it in the session's revision and
// publishes "REVISION " + ARGV[4] + frame, all at once: the revision orders changes for every
// instance. KEYS[1] the state hash; ARGV: field, frame, channel, the rest of the header.
constexpr std::string_view kPublish = R"lua(
redis.call('HSET', KEYS[1], ARGV[1], ARGV[2])
local revision = redis.call('HINCRBY', KEYS[1], 'revision', 1)
redis.call('PUBLISH', ARGV[3], revision .. ' ' .. ARGV[4] .. ARGV[2])
return revision)lua";

// The session's state whole, seeded with this instance's own when the broker has none.
// KEYS[1] the state hash; ARGV: revision, REV, then field, frame pairs.
// A session's definition (KEYS[1] field ARGV[1]) and its state (KEYS[2]) deleted if the
// definition is still ARGV[2].
constexpr std::string_view kRemoveIfSame = R"lua(
if redis.call('HGET', KEYS[1], ARGV[1]) == ARGV[2] then
  redis.call('HDEL', KEYS[1], ARGV[1])
  redis.call('DEL', KEYS[2])
  return 1
end
return 0
)lua";

constexpr std::string_view kSeedAndRead = R"lua(
if redis.call('EXISTS', KEYS[1]) == 0 then redis.call('HSET', KEYS[1], unpack(ARGV)) end
return redis.call('HGETALL', KEYS[1]))lua";

// What EVALSHA names a script by: the SHA-1 of its text, in hex.
std::string script_digest(std::string_view script) {
  unsigned char digest[SHA_DIGEST_LENGTH];
  SHA1(reinterpret_cast<const unsigned char*>(script.data()), script.size(), digest);
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (const unsigned char b : digest) out += hex[b >> 4], out += hex[b & 15];
  return out;
}

// Whether applying `change` would change the snapshot's state.
bool differs(const Snapshot& s, const Message& change) {
  if (const auto* m = std::get_if<StyleChange>(&change)) return !(*m == s.style);
  if (const auto* m = std::get_if<CameraPose>(&change)) return !(*m == s.camera);
  if (const auto* m = std::get_if<ObjectPose>(&change)) return !(*m == s.object);
  if (const auto* m = std::get_if<ExpressionCode>(&change)) return !(*m == s.expression);
  return false;
}

std::string_view text_of(const redisReply* r) { return r && r->str ? std::string_view(r->str, r->len) : std::string_view(); }
bool is_error(const redisReply* r) { return !r || r->type == REDIS_REPLY_ERROR; }
std::string reason_of(const redisReply* r) { return r ? std::string(text_of(r)) : "the broker went away"; }

int64_t now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

BrokerAddress parse_broker(const std::string& url) {
  constexpr std::string_view scheme = "redis://";
  if (url.rfind("nats://", 0) == 0) throw Error("broker '" + url + "': this build relays through Redis; give redis://HOST:PORT");
  if (url.rfind(scheme, 0) != 0) throw Error("broker '" + url + "' is not redis://HOST:PORT");
  std::string rest = url.substr(scheme.size());
  BrokerAddress a;
  // redis://[[USER]:PASSWORD@]HOST[:PORT]
  if (const size_t at = rest.rfind('@'); at != std::string::npos) {
    const std::string credentials = rest.substr(0, at);
    const size_t colon = credentials.find(':');
    if (colon == std::string::npos) throw Error("broker URL: credentials go as :PASSWORD@ or USER:PASSWORD@");
    a.user = credentials.substr(0, colon);
    a.password = credentials.substr(colon + 1);
    rest = rest.substr(at + 1);
  }
  const size_t colon = rest.rfind(':');
  a.host = rest.substr(0, colon);
  if (colon != std::string::npos) {
    const std::string port = rest.substr(colon + 1);
    unsigned value = 0;
    const auto [p, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
    if (ec != std::errc() || p != port.data() + port.size() || value == 0 || value > 65535)
      throw Error("broker '" + url + "': port '" + port + "' is not 1-65535");
    a.port = uint16_t(value);
  }
  if (a.host.empty()) throw Error("broker '" + url + "' names no host");
  return a;
}

RedisRelay::RedisRelay(SessionFanout& sessions, BrokerAddress address)
    : sessions_(sessions), address_(std::move(address)), io_(sessions.io()), commands_(io_), events_(io_), retry_timer_(io_), heartbeat_timer_(io_),
      publish_digest_(script_digest(kPublish)) {
  status_.broker = true;
  status_.connected = false;
}

RedisRelay::~RedisRelay() { stop(); }

void RedisRelay::start() {
  log_info("broker-connecting", {{"broker", "redis://" + address_.host + ":" + std::to_string(address_.port)}, {"password", !address_.password.empty()}});
  connect();
}

void RedisRelay::stop() {
  stopped_ = true;
  ready_ = false;
  retry_timer_.cancel();
  heartbeat_timer_.cancel();
  commands_.disconnect();
  events_.disconnect();
}

RelayStatus RedisRelay::status() const {
  RelayStatus s = status_;
  s.connected = ready_;
  s.outbox = unsent_.size();
  return s;
}

void RedisRelay::connect() {
  connections_up_ = 0;
  subscriptions_ = 0;
  const auto up = [this] {
    if (++connections_up_ < 2) return;
    if (!events_.subscribe({kEvents, kNotices, kCalls}, [this](const redisReply* r) { on_subscription(r); }))
      lost("cannot subscribe");
  };
  // A broker with a password hears it first on each connection.
  const auto authenticated = [this, up](RedisConnection& connection) {
    return [this, up, &connection] {
      if (address_.password.empty()) return up();
      std::vector<std::string_view> auth{"AUTH"};
      if (!address_.user.empty()) auth.push_back(address_.user);
      auth.push_back(address_.password);
      connection.command(auth, [this, up](const redisReply* r) {
        if (is_error(r)) return lost("the broker refused the password: " + reason_of(r));
        up();
      });
    };
  };
  const auto down = [this](const std::string& reason) { lost(reason); };
  commands_.connect(address_.host, address_.port, 2s, authenticated(commands_), down);
  events_.connect(address_.host, address_.port, 2s, authenticated(events_), down);
}

void RedisRelay::lost(const std::string& reason) {
  if (stopped_ || retry_scheduled_) return;
  const bool was_ready = std::exchange(ready_, false);
  retry_scheduled_ = true;
  // Replies still pending are answered with null now: their changes are applied here and kept.
  commands_.disconnect();
  events_.disconnect();
  for (auto& [name, order] : orders_) order.broker_lost();
  log(LogLevel::Warn, was_ready ? "broker-lost" : "broker-unreachable",
      {{"reason", reason}, {"retry_ms", backoff_.count()}, {"serving", "own members only"}});
  retry_timer_.expires_after(backoff_);
  backoff_ = std::min<std::chrono::milliseconds>(backoff_ * 2, 5s);
  retry_timer_.async_wait([this](std::error_code ec) {
    retry_scheduled_ = false;
    if (!ec && !stopped_) connect();
  });
}

void RedisRelay::on_subscription(const redisReply* r) {
  if (!r || r->type != REDIS_REPLY_ARRAY || r->elements < 3) return;  // null: `lost` follows
  const std::string_view kind = text_of(r->element[0]), channel = text_of(r->element[1]);
  if (kind == "subscribe") {
    if (++subscriptions_ == 3) ready();
    return;
  }
  if (kind != "message") return;
  if (channel == kEvents) on_event(text_of(r->element[2]));
  else if (channel == kNotices) {
    // Only the session named: every instance reading every definition at each notice costs the
    // square of the sessions when rooms open by the thousand.
    const std::string name(text_of(r->element[2]));
    commands_.command({"HGET", kSessions, name}, [this, name](const redisReply* r) {
      if (is_error(r)) return;
      if (r->type == REDIS_REPLY_STRING) take_definition(name, text_of(r));
      else if (r->type == REDIS_REPLY_NIL) removed_elsewhere(name);
    });
  }
  else if (channel == kCalls) on_call(text_of(r->element[2]));
}

// Calls are live traffic, not state: published as they happen and lost while the broker is away
// (each instance's own members still hear one another).
void RedisRelay::share_call(const CallShare& share) {
  if (!ready_) return;
  const std::string text = call_share(share);
  commands_.command({"PUBLISH", kCalls, text}, [](const redisReply*) {});
}

void RedisRelay::on_call(std::string_view payload) {
  try {
    CallShare share = parse_call_share(payload);
    if (share.origin == sessions_.instance_name()) return;  // its own
    if (const auto session = sessions_.find_session(share.session); session && session->call()) session->call()->remote(share);
  } catch (const protocol::ProtocolError& e) {
    log_warn("broker-call-garbled", {{"reason", e.what()}});
  }
}

// A broker that stops answering without closing its sockets (stopped, partitioned, swapping)
// would hold every change forever: a PING each second, and no answer within the deadline is a
// lost broker (hiredis 0.14 has no command timeout of its own).
void RedisRelay::heartbeat() {
  heartbeat_timer_.expires_after(1s);
  heartbeat_timer_.async_wait([this](std::error_code ec) {
    if (ec || stopped_ || !ready_) return;
    if (ping_outstanding_ && Clock::now() - ping_sent_ > kHeartbeatDeadline) {
      lost("the broker did not answer a PING within " + std::to_string(kHeartbeatDeadline.count()) + " ms");
      return;
    }
    if (!ping_outstanding_) {
      ping_outstanding_ = true;
      ping_sent_ = Clock::now();
      const uint64_t round = ++ping_round_;
      commands_.command({"PING"}, [this, round](const redisReply* r) {
        if (r && round == ping_round_) ping_outstanding_ = false;
      });
    }
    heartbeat();
  });
}

void RedisRelay::ready() {
  ready_ = true;
  ping_outstanding_ = false;
  heartbeat();
  commands_.command({"SCRIPT", "LOAD", kPublish}, [](const redisReply*) {});  // before any EVALSHA: one connection keeps order
  backoff_ = 100ms;
  if (std::exchange(ever_ready_, true)) ++status_.reconnects;
  log_info("broker-connected", {{"instance", sessions_.instance_name()}, {"unsent", unsent_.size()}});
  // Every session waits for its resync from here on, so no change is applied out of order. Each
  // resync sends the changes made here while the broker was away that it does not hold yet.
  for (const auto& [name, session] : sessions_.sessions()) orders_[name].resync_started();
  for (const auto& [name, session] : sessions_.sessions()) share(*session);
  discover();
  for (const auto& [name, session] : sessions_.sessions()) resync(name);
}

void RedisRelay::publish(Session& session, const Message& change, uint64_t sender) {
  const std::string field = state_field(change);
  const Bytes frame = encode(change);
  if (!ready_) {
    sessions_.deliver(session, change, sender);
    keep_unsent(session.name(), field, frame, sender);
    return;
  }
  send_change(session.name(), field, frame, sender);
}

void RedisRelay::keep_unsent(const std::string& session, const std::string& field, const Bytes& frame, uint64_t sender) {
  unsent_[{session, field}] = {frame, sender};
}

void RedisRelay::send_change(const std::string& session, const std::string& field, const Bytes& frame, uint64_t sender, bool by_digest) {
  const std::string key = state_key(session);
  const std::string header = event_header(now_us(), sender, sessions_.instance_name(), session);
  const std::string_view bytes(reinterpret_cast<const char*>(frame.data()), frame.size());
  // By the script's digest (loaded on connecting): Redis then neither receives nor hashes the
  // script's text for every change.
  const std::vector<std::string_view> call{by_digest ? "EVALSHA" : "EVAL", by_digest ? std::string_view(publish_digest_) : kPublish, "1", key, field,
                                           bytes, kEvents, header};
  const bool sent = commands_.command(call, [this, session, field, frame, sender](const redisReply* r) {
    if (!is_error(r)) return;
    if (r && text_of(r).starts_with("NOSCRIPT")) return send_change(session, field, frame, sender, false);  // its script cache was flushed
    // Not known to be published: applied here at once, and sent again once the broker is back.
    log_warn("broker-publish-failed", {{"session", session}, {"field", field}, {"reason", reason_of(r)}});
    if (const auto s = sessions_.find_session(session)) {
      sessions_.deliver(*s, decode_frame(frame.data(), frame.size()), sender);
      keep_unsent(session, field, frame, sender);
    }
  });
  if (sent) ++status_.published;
  else keep_unsent(session, field, frame, sender);
}

void RedisRelay::on_event(std::string_view payload) {
  Event e;
  try {
    e = parse_event(payload);
  } catch (const std::exception& ex) {
    log_warn("broker-event-malformed", {{"bytes", payload.size()}, {"reason", ex.what()}});
    return;
  }
  ++status_.received;
  if (e.origin == sessions_.instance_name()) status_.lag_seconds = double(now_us() - e.published_us) / 1e6;
  const auto session = sessions_.find_session(e.session);
  if (!session) return;  // not here (yet): adopted with its state when its notice comes
  ChangeOrder& order = orders_[e.session];
  follow(*session, order, order.arrive(std::move(e)));
}

void RedisRelay::follow(Session& session, ChangeOrder& order, ChangeOrder::Arrival arrival) {
  if (arrival.dropped > 0) {
    ++status_.overflows;
    log_warn("broker-waiting-overflow", {{"session", session.name()}, {"dropped", arrival.dropped}});
  }
  if (const auto& e = arrival.apply) sessions_.deliver(session, e->change, e->origin == sessions_.instance_name() ? e->sender : 0, e->revision);
  if (arrival.resync && !order.syncing()) resync(session.name());
}

void RedisRelay::resync(const std::string& name) {
  const auto session = sessions_.find_session(name);
  if (!session) return;
  orders_[name].resync_started();
  ++status_.resyncs;
  const Snapshot& s = session->state();
  std::vector<std::string> own{"revision", std::to_string(s.revision)};
  for (const Message& m : {Message(s.style), Message(s.camera), Message(s.object), Message(s.expression)}) {
    const Bytes frame = encode(m);
    own.push_back(state_field(m));
    own.emplace_back(frame.begin(), frame.end());
  }
  std::vector<std::string_view> args{"EVAL", kSeedAndRead, "1"};
  const std::string key = state_key(name);
  args.push_back(key);
  args.insert(args.end(), own.begin(), own.end());
  const bool sent = commands_.command(args, [this, name](const redisReply* r) {
    ChangeOrder& order = orders_[name];
    const auto session = sessions_.find_session(name);
    if (!session) {
      order.resync_abandoned();
      return;
    }
    if (!r) return;  // the broker went away: reconnecting resyncs every session
    if (is_error(r) || r->type != REDIS_REPLY_ARRAY) {
      log_warn("broker-resync-failed", {{"session", name}, {"reason", reason_of(r)}, {"retry_ms", 500}});
      retry_resync(name);
      return;
    }
    // A revision that does not read as a number is refused, not taken for 0 (which would apply
    // every change again).
    std::optional<uint64_t> revision;
    for (size_t i = 0; i + 1 < r->elements; i += 2)
      if (text_of(r->element[i]) == "revision") {
        const std::string_view value = text_of(r->element[i + 1]);
        uint64_t n = 0;
        const auto [p, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (ec == std::errc() && p == value.data() + value.size() && n <= UINT32_MAX) revision = n;
      }
    if (!revision) {
      log_warn("broker-resync-failed", {{"session", name}, {"reason", "the broker's revision of the session is missing or garbled"}, {"retry_ms", 500}});
      retry_resync(name);
      return;
    }
    for (size_t i = 0; i + 1 < r->elements; i += 2) {
      const std::string_view field = text_of(r->element[i]), value = text_of(r->element[i + 1]);
      if (field == "revision") continue;
      // A change made here while away: already applied here, and sent below unless the broker has it.
      if (const auto mine = unsent_.find({name, std::string(field)}); mine != unsent_.end()) {
        if (std::string_view(reinterpret_cast<const char*>(mine->second.frame.data()), mine->second.frame.size()) == value) unsent_.erase(mine);
        continue;
      }
      try {
        const Message change = decode_frame(reinterpret_cast<const uint8_t*>(value.data()), value.size());
        if (state_field(change) != field) continue;
        if (differs(session->state(), change)) sessions_.deliver(*session, change, 0);  // members hear only what changed
      } catch (const std::exception& e) {
        log_warn("broker-state-malformed", {{"session", name}, {"field", field}, {"reason", e.what()}});
      }
    }
    ChangeOrder::Resynced next = order.resynced(uint32_t(*revision));
    session->set_revision(order.revision());
    for (auto it = unsent_.lower_bound({name, ""}); it != unsent_.end() && it->first.first == name; it = unsent_.erase(it))
      send_change(name, it->first.second, it->second.frame, it->second.sender);
    for (const Event& e : next.apply) sessions_.deliver(*session, e.change, e.origin == sessions_.instance_name() ? e.sender : 0, e.revision);
    if (next.resync) resync(name);
  });
  if (!sent) orders_[name].resync_abandoned();  // not connected: the reconnection resyncs
}

void RedisRelay::retry_resync(const std::string& name) {
  auto timer = std::make_shared<asio::steady_timer>(io_, 500ms);
  timer->async_wait([this, name, timer](std::error_code ec) {
    if (!ec && !stopped_ && ready_) resync(name);
  });
}

void RedisRelay::session_added(const Session& session) {
  if (!ready_) return;  // shared with the others when the broker is back
  share(session);
  resync(session.name());
}

// A session gone here. A call room empty too long: its definition and state leave the broker
// only if they are still the ones shared here, so a room of the same name opened since on another
// instance stays. A product or scene removed by its operator: gone from the broker whoever shared
// it last, and the notice that follows (a name with no definition) has every other instance drop
// its copy, so none shares it again when it restarts.
void RedisRelay::session_removed(const Session& session) {
  const std::string name = session.name();
  orders_.erase(name);
  const auto shared = definitions_.find(name);
  if (shared == definitions_.end()) return;
  const std::string definition = std::move(shared->second);
  definitions_.erase(shared);
  if (!ready_) return;
  const auto refused = [name](const redisReply* r) {
    if (is_error(r)) log_warn("broker-session-not-removed", {{"session", name}, {"reason", reason_of(r)}});
  };
  if (session.state().kind == SessionKind::Conference) {
    commands_.command({"EVAL", kRemoveIfSame, "2", kSessions, state_key(name), name, definition}, refused);
    return;
  }
  commands_.command({"HDEL", kSessions, name}, refused);
  commands_.command({"DEL", state_key(name)}, refused);
  commands_.command({"PUBLISH", kNotices, name}, [](const redisReply*) {});
}

// A notice naming a session the broker no longer defines: removed on the instance that sent it.
// Call rooms are not dropped so (each instance's copy goes when idle there).
void RedisRelay::removed_elsewhere(const std::string& name) {
  const std::shared_ptr<Session> served = sessions_.find_session(name);
  if (!served || served->state().kind == SessionKind::Conference || adopting_.count(name)) return;
  log_info("broker-session-removed", {{"session", name}, {"members", served->members()}});
  sessions_.remove_session(name);
}

void RedisRelay::share(const Session& session) {
  const std::string name = session.name();
  const std::string definition = session_definition(session.stored());
  // What this instance knows the session by in the broker: its own, unless another's was there first.
  definitions_.try_emplace(name, definition);
  commands_.command({"HSETNX", kSessions, name, definition}, [this, name](const redisReply* r) {
    if (is_error(r)) return;
    if (r->type == REDIS_REPLY_INTEGER && r->integer == 1) {
      log_info("broker-session-shared", {{"session", name}});
      commands_.command({"PUBLISH", kNotices, name}, [](const redisReply*) {});
    }
  });
  for (const AssetAnnounce& asset : session.state().assets) share_asset(asset);
}

void RedisRelay::share_asset(const AssetAnnounce& asset) {
  if (asset.size > kMaxSharedAsset) {
    log_warn("broker-asset-not-shared", {{"asset", asset.name}, {"bytes", asset.size}, {"reason", "over 64 MiB: give the instances one data folder"}});
    return;
  }
  const std::string key = asset_key(asset.hash);
  commands_.command({"EXISTS", key}, [this, key, asset](const redisReply* r) {
    if (is_error(r) || r->integer != 0) return;
    try {
      const Bytes bytes = sessions_.store().read_verified(asset.hash);
      commands_.command({"SET", key, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "NX"}, [](const redisReply*) {});
    } catch (const Error& e) {
      log_warn("broker-asset-not-shared", {{"asset", asset.name}, {"reason", e.what()}});
    }
  });
}

void RedisRelay::discover() {
  commands_.command({"HGETALL", kSessions}, [this](const redisReply* r) {
    if (is_error(r) || r->type != REDIS_REPLY_ARRAY) return;
    for (size_t i = 0; i + 1 < r->elements; i += 2) take_definition(std::string(text_of(r->element[i])), text_of(r->element[i + 1]));
  });
}

// A session's definition as the broker holds it under `name`, or nothing (logged) when it is
// malformed or defines another session.
std::optional<StoredSession> RedisRelay::read_definition(const std::string& name, std::string_view definition) {
  StoredSession stored;
  try {
    stored = parse_session_definition(definition);
  } catch (const std::exception& e) {
    log_warn("broker-session-malformed", {{"session", name}, {"reason", e.what()}});
    return std::nullopt;
  }
  if (stored.state.session != name) {
    log_warn("broker-session-malformed", {{"session", name}, {"reason", "it defines '" + stored.state.session + "'"}});
    return std::nullopt;
  }
  return stored;
}

void RedisRelay::take_definition(const std::string& name, std::string_view definition) {
  if (adopting_.count(name)) return;
  const std::shared_ptr<Session> served = sessions_.find_session(name);
  if (!served) return adopt_remote(name, definition);
  if (const auto known = definitions_.find(name); known != definitions_.end() && known->second == definition) return;
  std::optional<StoredSession> stored = read_definition(name, definition);
  if (!stored) return;
  // Only a made scene's model changes while it runs (its editor's new upload); other differences
  // (the same name configured otherwise on two instances) are left as they are.
  const auto mesh = [](const protocol::Snapshot& s) {
    for (const AssetAnnounce& a : s.assets)
      if (a.kind == AssetKind::Mesh) return std::optional(a);
    return std::optional<AssetAnnounce>();
  };
  const bool scene = served->state().kind == SessionKind::Scene && served->state().product.directions.empty() && stored->state.kind == SessionKind::Scene &&
                     served->stored().maker != MadeBy::Operator;
  if (!scene || !mesh(stored->state) || mesh(stored->state) == mesh(served->state())) return;
  adopt_model(name, definition, std::move(*stored));
}

// Another instance's editor gave a scene served here a new model: fetched, then every member
// here gets it (its style and camera kept, as on the instance it was uploaded to).
void RedisRelay::adopt_model(const std::string& name, std::string_view definition, StoredSession stored) {
  adopting_.insert(name);
  definitions_[name] = std::string(definition);
  const std::vector<AssetAnnounce> assets = stored.state.assets;
  fetch_missing(name, assets, [this, name, assets](bool fetched) {
    adopting_.erase(name);
    const std::shared_ptr<Session> session = sessions_.find_session(name);
    if (!fetched || !session) return;
    for (const AssetAnnounce& a : assets)
      if (a.kind == AssetKind::Mesh) {
        session->replace_model(a);
        log_info("broker-model-replaced", {{"session", name}, {"model", a.name}, {"members", session->members()}});
        return;
      }
  });
}

// The new model goes to the broker before the definition naming it (one connection keeps the
// order), then the notice that brings the other instances to read it.
void RedisRelay::model_replaced(const Session& session) {
  const std::string name = session.name();
  const std::string definition = session_definition(session.stored());
  definitions_[name] = definition;
  if (!ready_) return;
  for (const AssetAnnounce& asset : session.state().assets) share_asset(asset);
  commands_.command({"HSET", kSessions, name, definition}, [this, name](const redisReply* r) {
    if (is_error(r)) return log_warn("broker-session-not-shared", {{"session", name}, {"reason", reason_of(r)}});
    commands_.command({"PUBLISH", kNotices, name}, [](const redisReply*) {});
  });
}

// A session another instance shared: its assets are fetched, checked against their hashes and
// stored, then the session is served here too.
void RedisRelay::adopt_remote(const std::string& name, std::string_view definition) {
  std::optional<StoredSession> stored = read_definition(name, definition);
  if (!stored) return;
  adopting_.insert(name);
  definitions_[name] = std::string(definition);
  auto session = std::make_shared<StoredSession>(std::move(*stored));
  fetch_missing(name, session->state.assets, [this, name, session](bool fetched) {
    adopting_.erase(name);
    if (!fetched || sessions_.find_session(name)) return;
    if (sessions_.add_session(std::move(*session))) resync(name);
  });
}

void RedisRelay::fetch_missing(const std::string& name, const std::vector<AssetAnnounce>& assets, std::function<void(bool)> done) {
  auto missing = std::make_shared<std::vector<AssetAnnounce>>();
  for (const AssetAnnounce& a : assets)
    if (!sessions_.store().find(a.hash)) missing->push_back(a);
  auto left = std::make_shared<size_t>(missing->size());
  auto failed = std::make_shared<bool>(false);
  const auto finish = [failed, done = std::move(done)] { done(!*failed); };
  if (missing->empty()) return finish();
  for (const AssetAnnounce& asset : *missing) {
    const bool sent = commands_.command({"GET", asset_key(asset.hash)}, [this, name, asset, left, failed, finish](const redisReply* r) {
      if (is_error(r) || r->type != REDIS_REPLY_STRING) {
        if (!*failed) log_warn("broker-asset-missing", {{"session", name}, {"asset", asset.name}, {"reason", r ? "not in the broker" : "the broker went away"}});
        *failed = true;
      } else {
        const std::string_view bytes = text_of(r);
        if (content_hash(bytes.data(), bytes.size()) != asset.hash) {
          log_warn("broker-asset-corrupted", {{"session", name}, {"asset", asset.name}, {"reason", "does not match its hash"}});
          *failed = true;
        } else {
          try {
            sessions_.store().add_bytes(Bytes(bytes.begin(), bytes.end()), asset.kind, asset.name);
          } catch (const Error& e) {
            log(LogLevel::Error, "broker-asset-not-stored", {{"session", name}, {"asset", asset.name}, {"reason", e.what()}});
            *failed = true;
          }
        }
      }
      if (--*left == 0) finish();
    });
    // Not sent (the broker went away meanwhile): the fetch fails now instead of never ending;
    // the next discovery after the broker is back tries again.
    if (!sent) {
      *failed = true;
      if (--*left == 0) finish();
    }
  }
}

}  // namespace inkwire::server
