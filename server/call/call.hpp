#pragma once
// A call (SPEC F7-F13): the members of one conference session who publish their own face and
// voice, as the I/O thread keeps them. Each member has a number, a name, what it publishes, its
// neutral photo and landmarks (in memory, as assets), its voice's level and mouth; crops go to
// the analyst (call_analyst.hpp) and what it reads comes back as member-face messages; voice is
// relayed as it came to everyone else while its sender is among the K loudest. Members only
// ever publish as themselves: the member number on what is relayed is the sender's own.
// What is dropped (too frequent, too large, not JPEG, not Opus) is counted by reason; a member
// that keeps flooding is closed with the reason. With several instances (a broker), what the
// members here publish is shared through the relay, and the members of other instances join the
// roster under numbers of this instance's own: their voice and faces come to the members here
// as any member's (each instance relays its own K loudest).
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "protocol/messages.hpp"
#include "server/call/call_analyst.hpp"
#include "server/call/call_options.hpp"
#include "server/call/voice_analysis.hpp"

namespace inkwire::server {

class CallPeer;
class Relay;
struct CallShare;


class Call {
 public:
  using Clock = std::chrono::steady_clock;
  // For /metrics and the benchmark, shared by every call of the server: crops analysed and the
  // analyst's time on them (server CPU per publisher), voice packets relayed (one per
  // receiver), messages dropped by reason.
  struct Counters {
    uint64_t crops = 0;
    double seconds = 0;
    uint64_t voice_relayed = 0;
    std::map<std::string, uint64_t> drops;
  };

  // `origin`: this instance's name, on what it shares through `relay`.
  Call(std::string session, CallOptions options, CallAnalyst& analyst, Counters& counters, Relay& relay, std::string origin);
  ~Call();

  // `host`: the member joined with the room's host key (SPEC N7).
  void join(const std::shared_ptr<CallPeer>& connection, const std::string& name, bool host = false);
  void leave(uint64_t connection);

  // The room's host controls (SPEC N7): a locked room takes no newcomers but its host; a member
  // removed is closed with error 12 and the reason. False when no member has that number.
  // With several instances the room is one: the instance its host is on says whether it is
  // locked (in the roster it shares), and a member of another instance is removed there.
  bool locked() const { return locked_; }
  void set_locked(bool locked);
  bool remove(uint16_t member, const std::string& reason);
  // The name of the host while it is in the call (on any instance), else empty.
  std::string host_name() const;
  // Members of other instances in the roster now.
  size_t remote_members() const { return remotes_.size(); }

  // From a member's connection.
  void publish(uint64_t connection, const protocol::Publish& publish);
  void photo(uint64_t connection, protocol::Bytes jpeg);
  void crop(uint64_t connection, protocol::FaceCrop crop);
  void video(uint64_t connection, protocol::FaceVideo frame);
  void voice(uint64_t connection, protocol::VoiceFrame frame);

  // A few times a second: speakers who fell silent stop speaking; other instances hear this
  // one's roster again, and members of instances not heard from lately leave.
  void tick();
  // What another instance's members publish (through the broker).
  void remote(const CallShare& share);

  // From the analyst, on the I/O thread.
  void analysed(const PhotoAnalysed& result);
  void analysed(const CropAnalysed& result);

  // A member's photo or landmarks by hash: its bytes, or null unless a member holds it.
  const protocol::Bytes* asset(const protocol::Hash& hash) const;
  size_t size() const { return members_.size(); }

 private:
  struct Member;
  Member* find(uint64_t connection);
  Member* find_member(uint16_t number);
  // Counts a drop; true when the member has dropped so much in the last second that it floods
  // (it is then closed with the reason).
  bool dropped(Member& m, const std::string& reason);
  // Sends the member a key-frame-request, at most twice a second.
  void ask_for_key_frame(Member& m);
  // Within the member's rate and size for a crop or a voice packet; otherwise dropped and counted.
  bool admitted(Member& m, bool voice, size_t size);
  void send_roster();
  size_t send_to_others(const Member& from, const protocol::Message& message);  // how many it went to
  void send_to_all(const protocol::Message& message);
  // A member's face to every member here, each in the version it reads (member-face for a peer
  // of version 7 or 8).
  void send_face(const protocol::MemberLayers& face);
  // The member's face to every member here and to the other instances, within its budget
  // (kFacesPerSecond): one that finds no room waits, replaced by any newer one, and goes with the
  // member's next packet or crop that finds room.
  void offer_face(Member& m, const protocol::MemberLayers& face, Clock::time_point now);
  void send_waiting_face(Member& m, Clock::time_point now);
  void update_speakers(Clock::time_point now);

  std::string session_;
  bool locked_ = false;
  CallOptions options_;
  CallAnalyst& analyst_;
  Counters& counters_;
  std::map<uint64_t, std::unique_ptr<Member>> members_;  // by connection id
  uint16_t next_number_ = 1;
  // Who left lately, by name and address, with their number: one whose connection dropped comes
  // back under the same number, so the same tile (SPEC F19).
  struct Departed {
    uint16_t member;
    Clock::time_point when;
  };
  std::map<std::pair<std::string, std::string>, Departed> departed_;
  // The number a member joining as `name` from `address` takes: its own of a minute ago when it
  // comes back, else a new one. A twin of it still here and silent past two heartbeats (its
  // connection dropped without a word) gives way first.
  uint16_t number_for(const std::string& name, const std::string& address);
  uint16_t take_number();
  void share_roster();

  // Members of other instances: their entry under a number of this instance, their photo's bytes.
  // Their voice is read here too (level, when last heard), so every instance picks the same
  // loudest few across the whole call (SPEC F19), not a few of its own each.
  struct Remote {
    protocol::CallMember entry;
    bool host = false;  // the room's host, by its origin's roster
    std::map<protocol::Hash, protocol::Bytes> asset_bytes;
    Clock::time_point heard;
    VoiceAnalysis voice;
    float level_db = -100;
    Clock::time_point last_voice{};
  };
  std::map<std::pair<std::string, uint16_t>, Remote> remotes_;  // by (origin, the origin's number)
  Remote* remote_member(const std::string& origin, uint16_t number, bool create);
  Relay& relay_;
  std::string origin_;
  Clock::time_point roster_shared_{};
};

}  // namespace inkwire::server
