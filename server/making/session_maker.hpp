#pragma once
// Sessions people make themselves (SPEC N6-N10): call rooms opened by their first member, scenes
// made from a model a visitor uploads, each under the operator's policy (who may, how many
// overall and per address, which names), and gone once unused for long enough (rooms after
// `room_idle_seconds` without members, uploaded scenes nobody kept after `scene_idle_seconds`).
// They go through the same registry, catalogue and broker as configured sessions, so nothing
// downstream knows the difference. Whoever makes one holds its key: a room's host key, a
// scene's editor token; the server keeps only their digests, as the session's editor token.
// Touched on the I/O thread only; time comes from the caller, so tests drive it.
#include <chrono>
#include <map>
#include <memory>
#include <string>

#include "server/asset_store.hpp"
#include "server/making/making_options.hpp"

namespace inkwire::server {

class Session;
class SessionRegistry;

// What /metrics counts of them.
struct MakingCounters {
  uint64_t rooms_opened = 0, rooms_expired = 0, scenes_made = 0, scenes_expired = 0, models_replaced = 0;
  std::map<std::string, uint64_t> refused;  // by reason: "policy", "token", "cap", "cap-per-address", "name", "size", "import", ...
};

class SessionMaker {
 public:
  using Clock = std::chrono::steady_clock;

  // `public_listener`: some listener is reachable from other machines (then the policy defaults
  // to the creator token). `limit_loopback`: the limits per address apply to 127.0.0.1 and ::1
  // too, as the config's limit_loopback says for connections; without it they leave this
  // machine alone (a proxy on it speaks for many people), and only the overall caps hold there.
  SessionMaker(const MakingOptions& options, bool public_listener, SessionRegistry& registry, bool limit_loopback = false);

  MakingPolicy policy() const { return policy_; }
  const MakingOptions& options() const { return options_; }

  // A session made, with the key its maker holds (shown once, never stored), or why not.
  struct Made {
    std::shared_ptr<Session> session;
    std::string key;
    std::string refusal;
    std::string reason_key;  // what /metrics counts the refusal under
  };

  // Opens call room `name` for `address`, who gave `token` (the creator token when the policy
  // asks for one).
  Made open_room(const std::string& name, const std::string& token, const std::string& address, Clock::time_point now);
  // Whether `address` may make a scene now (before its upload is read): empty, or the refusal.
  std::string may_make_scene(const std::string& token, const std::string& address, std::string* reason_key = nullptr) const;
  // A scene of the stored GLB `model` (already in the store), named afresh, its maker its editor.
  Made make_scene(const protocol::AssetAnnounce& model, const std::string& address, Clock::time_point now);
  // A running scene's model replaced (its style and camera kept): every member is sent the new
  // snapshot. Empty, or why not.
  std::string replace_model(Session& scene, const protocol::AssetAnnounce& model);

  // Sessions made on demand that have been unused past their time are removed (with the
  // registry's on_removed). `members(session)` counts a session's members on every instance
  // this one knows of.
  void sweep(Clock::time_point now);

  // Whether `address` may begin an upload now: within uploads_per_minute_per_address (a burst of
  // a minute's worth at most) and within the uploads being received at once, from it and in
  // all. Otherwise the refusal, and in `retry_after` the seconds to wait. A begun upload ends
  // with upload_done(address).
  std::string take_upload(const std::string& address, Clock::time_point now, double* retry_after);
  void upload_done(const std::string& address);
  static constexpr int kMaxUploadsAtOnce = 16, kMaxUploadsPerAddress = 2;
  // Whether an upload received whole may be imported now (an importer may use
  // import_memory_bytes): at most kMaxImportsAtOnce run; one taken ends with import_done(). An
  // upload's body is no import: a sender that stalls holds no import's place.
  bool take_import();
  void import_done() { --imports_running_; }
  static constexpr int kMaxImportsAtOnce = 2;

  // A refusal counted under `reason_key` (uploads refused for their size or content).
  void count_refusal(const std::string& reason_key) { ++counters_.refused[reason_key]; }
  const MakingCounters& counters() const { return counters_; }
  size_t open_rooms() const;
  size_t open_scenes() const;

  // A new unguessable session name: 96 random bits, URL-safe (16 characters).
  static std::string random_name();

 private:
  std::string refusal_for(MadeBy maker, const std::string& token, const std::string& address, std::string* reason_key) const;
  std::string policy_refusal(MadeBy maker, const std::string& token, std::string* reason_key) const;  // who may
  std::string cap_refusal(MadeBy maker, const std::string& address, std::string* reason_key) const;   // how many

  size_t count_made(MadeBy maker, const std::string& address) const;  // every address when empty
  bool limited(const std::string& address) const;                     // whether the per-address limits apply to it

  MakingOptions options_;
  MakingPolicy policy_;
  bool limit_loopback_;
  std::string creator_token_hash_;
  SessionRegistry& registry_;
  std::map<std::string, Clock::time_point> unused_since_;  // sessions made on demand without members, since when
  struct Allowance {
    double uploads = 0;
    Clock::time_point at{};
  };
  std::map<std::string, Allowance> upload_allowance_;  // per address: uploads it may still make now
  int uploads_running_ = 0, imports_running_ = 0;
  std::map<std::string, int> uploads_from_;  // uploads being received, by (limited) address
  MakingCounters counters_;
};

}  // namespace inkwire::server
