#include "server/making/session_maker.hpp"

#include <algorithm>
#include <cmath>
#include <openssl/rand.h>

#include <asio/ip/address.hpp>

#include "common/error.hpp"
#include "common/log.hpp"
#include "server/session.hpp"
#include "server/session_registry.hpp"
#include "server/session_token.hpp"

namespace inkwire::server {
namespace {

// Letters, digits and - _ . (the protocol's session names), at most `max` of them.
bool good_name(const std::string& name, size_t max) {
  return !name.empty() && name.size() <= max &&
         name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") == std::string::npos;
}

}  // namespace

SessionMaker::SessionMaker(const MakingOptions& options, bool public_listener, SessionRegistry& registry, bool limit_loopback)
    : options_(options),
      policy_(options.who_given ? options.who : public_listener ? MakingPolicy::Token : MakingPolicy::Anyone),
      limit_loopback_(limit_loopback),
      creator_token_hash_(hash_token(options.creator_token)),
      registry_(registry) {}

std::string SessionMaker::random_name() {
  unsigned char bytes[12];
  if (RAND_bytes(bytes, sizeof bytes) != 1) throw Error("no randomness for a session name");
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  std::string name;
  for (size_t i = 0; i < sizeof bytes; i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8 | bytes[i + 2];
    for (int k = 3; k >= 0; --k) name += digits[(n >> (6 * k)) & 63];
  }
  return name;
}

size_t SessionMaker::count_made(MadeBy maker, const std::string& address) const {
  size_t n = 0;
  for (const auto& [name, session] : registry_.all())
    if (session->stored().maker == maker && (address.empty() || session->stored().creator == address)) ++n;
  return n;
}

bool SessionMaker::limited(const std::string& address) const {
  std::error_code ec;
  const auto ip = asio::ip::make_address(address, ec);
  return limit_loopback_ || ec || !ip.is_loopback();
}

size_t SessionMaker::open_rooms() const { return count_made(MadeBy::Room, ""); }
size_t SessionMaker::open_scenes() const { return count_made(MadeBy::Upload, ""); }

std::string SessionMaker::refusal_for(MadeBy maker, const std::string& token, const std::string& address, std::string* reason_key) const {
  const std::string refused = policy_refusal(maker, token, reason_key);
  return refused.empty() ? cap_refusal(maker, address, reason_key) : refused;
}

std::string SessionMaker::policy_refusal(MadeBy maker, const std::string& token, std::string* reason_key) const {
  const char* what = maker == MadeBy::Room ? "open call rooms" : "make scenes";
  if (policy_ == MakingPolicy::Off) {
    if (reason_key) *reason_key = "policy";
    return std::string("this server does not let visitors ") + what;
  }
  if (policy_ == MakingPolicy::Token && (creator_token_hash_.empty() || !token_matches(creator_token_hash_, token))) {
    if (reason_key) *reason_key = "token";
    return std::string("only holders of this server's creator token may ") + what + (token.empty() ? "" : ": wrong token");
  }
  return "";
}

std::string SessionMaker::cap_refusal(MadeBy maker, const std::string& address, std::string* reason_key) const {
  const bool room = maker == MadeBy::Room;
  const size_t cap = room ? options_.max_rooms : options_.max_scenes, per_address = room ? options_.max_rooms_per_address : options_.max_scenes_per_address;
  const char* kinds = room ? "rooms" : "scenes";
  if (count_made(maker, "") >= cap) {
    if (reason_key) *reason_key = "cap";
    return std::string("this server has as many ") + kinds + " open as it takes (" + std::to_string(cap) + ")";
  }
  if (limited(address) && count_made(maker, address) >= per_address) {
    if (reason_key) *reason_key = "cap-per-address";
    return "your address has " + std::to_string(per_address) + " " + kinds + " open already, as many as this server allows one address";
  }
  return "";
}

SessionMaker::Made SessionMaker::open_room(const std::string& name, const std::string& token, const std::string& address, Clock::time_point now) {
  Made made;
  if (!good_name(name, options_.max_name_length)) {
    made.reason_key = "name";
    made.refusal = "a room's name is 1-" + std::to_string(options_.max_name_length) + " letters, digits, - _ .";
  } else {
    made.refusal = refusal_for(MadeBy::Room, token, address, &made.reason_key);
  }
  if (!made.refusal.empty()) {
    ++counters_.refused[made.reason_key];
    return made;
  }
  made.key = random_hex(protocol::kHostKeyChars / 2);
  StoredSession stored{.token = "", .editor_token = hash_token(made.key), .state = fresh_session_state(name, protocol::SessionKind::Conference, "default"),
                       .maker = MadeBy::Room, .creator = address, .kept = false};
  made.session = registry_.add(std::move(stored));
  if (!made.session) {
    made.refusal = "room " + name + " could not be opened";
    made.reason_key = "store";
    ++counters_.refused[made.reason_key];
    made.key.clear();
    return made;
  }
  unused_since_[name] = now;  // its opener joins at once; if not, it goes as an empty room does
  ++counters_.rooms_opened;
  log_info("room-opened", {{"session", name}, {"by", address}});
  return made;
}

std::string SessionMaker::may_make_scene(const std::string& token, const std::string& address, std::string* reason_key) const {
  return refusal_for(MadeBy::Upload, token, address, reason_key);
}

SessionMaker::Made SessionMaker::make_scene(const protocol::AssetAnnounce& model, const std::string& address, Clock::time_point now) {
  Made made;
  // The policy was checked before the upload was read; only the caps may have filled meanwhile.
  made.refusal = cap_refusal(MadeBy::Upload, address, &made.reason_key);
  if (!made.refusal.empty()) {
    ++counters_.refused[made.reason_key];
    return made;
  }
  std::string name;
  do name = random_name();
  while (registry_.find(name));
  made.key = random_hex(16);
  StoredSession stored{.token = "", .editor_token = hash_token(made.key), .state = fresh_session_state(name, protocol::SessionKind::Scene, "comic-extended"),
                       .maker = MadeBy::Upload, .creator = address, .kept = false};
  stored.state.assets.push_back(model);
  made.session = registry_.add(std::move(stored));
  if (!made.session) {
    made.refusal = "the scene could not be stored";
    made.reason_key = "store";
    ++counters_.refused[made.reason_key];
    made.key.clear();
    return made;
  }
  unused_since_[name] = now;  // nobody is in it yet: it goes if nobody comes
  ++counters_.scenes_made;
  log_info("scene-made", {{"session", name}, {"by", address}, {"model", model.name}, {"bytes", model.size}});
  return made;
}

std::string SessionMaker::replace_model(Session& scene, const protocol::AssetAnnounce& model) {
  if (scene.state().kind != protocol::SessionKind::Scene || !scene.state().product.directions.empty()) return "only a scene's model can be replaced";
  scene.replace_model(model);
  registry_.persist(scene);
  ++counters_.models_replaced;
  log_info("model-replaced", {{"session", scene.name()}, {"model", model.name}, {"bytes", model.size}, {"members", scene.members()}});
  return "";
}

std::string SessionMaker::take_upload(const std::string& address, Clock::time_point now, double* retry_after) {
  Allowance* allowance = nullptr;  // none for an address the per-address limits leave alone
  if (limited(address)) {
    const double rate = options_.uploads_per_minute_per_address / 60.0, burst = std::max(1.0, options_.uploads_per_minute_per_address);
    // Addresses whose allowance is full again are forgotten, so the map holds only the busy ones.
    std::erase_if(upload_allowance_, [&](const auto& a) { return a.second.uploads + rate * std::chrono::duration<double>(now - a.second.at).count() >= burst; });
    allowance = &upload_allowance_.try_emplace(address, Allowance{burst, now}).first->second;
    allowance->uploads = std::min(burst, allowance->uploads + rate * std::chrono::duration<double>(now - allowance->at).count());
    allowance->at = now;
    if (allowance->uploads < 1) {
      *retry_after = (1 - allowance->uploads) / rate;
      ++counters_.refused["rate"];
      return "too many uploads from your address: wait " + std::to_string(int(std::ceil(*retry_after))) + " s";
    }
  }
  if (allowance && uploads_from_[address] >= kMaxUploadsPerAddress) {
    *retry_after = 5;
    ++counters_.refused["busy-address"];
    return "your address is sending " + std::to_string(kMaxUploadsPerAddress) + " uploads already: wait for them to end";
  }
  if (uploads_running_ >= kMaxUploadsAtOnce) {
    *retry_after = 2;
    ++counters_.refused["busy"];
    return "this server is receiving as many uploads as it takes: try again in a moment";
  }
  if (allowance) allowance->uploads -= 1, ++uploads_from_[address];
  ++uploads_running_;
  return "";
}

void SessionMaker::upload_done(const std::string& address) {
  --uploads_running_;
  if (const auto it = uploads_from_.find(address); it != uploads_from_.end() && --it->second <= 0) uploads_from_.erase(it);
}

bool SessionMaker::take_import() {
  if (imports_running_ >= kMaxImportsAtOnce) return false;
  ++imports_running_;
  return true;
}

void SessionMaker::sweep(Clock::time_point now) {
  std::vector<std::string> gone;
  for (const auto& [name, session] : registry_.all()) {
    if (!session->stored().expires()) continue;
    if (session->members_everywhere() > 0) {
      unused_since_.erase(name);
      continue;
    }
    const auto [since, fresh] = unused_since_.try_emplace(name, now);
    const bool room = session->stored().maker == MadeBy::Room;
    const double idle = room ? options_.room_idle_seconds : options_.scene_idle_seconds;
    if (!fresh && now - since->second >= std::chrono::duration<double>(idle)) gone.push_back(name);
  }
  for (const std::string& name : gone) {
    const bool room = registry_.find(name)->stored().maker == MadeBy::Room;
    unused_since_.erase(name);
    if (!registry_.remove(name)) continue;
    ++(room ? counters_.rooms_expired : counters_.scenes_expired);
    log_info(room ? "room-gone" : "scene-gone", {{"session", name}});
  }
}

}  // namespace inkwire::server
