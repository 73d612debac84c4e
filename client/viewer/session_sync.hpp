#pragma once
// Keeps a SessionView in step with a SessionClient: takes each newer state, downloads assets it
// lists that are not cached yet (once; afterwards only control messages flow), and updates the
// view. Call poll() once per frame on the render thread. A product's photos are fetched and
// decoded on a thread of their own, one at a time, so the view keeps turning while they arrive.
#include <deque>
#include <future>
#include <map>

#include "client/call/call_audio.hpp"
#include "client/net/asset_cache.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"

namespace inkwire {

class SessionSync {
 public:
  SessionSync(SessionClient& client, AssetCache& cache) : client_(client), cache_(cache) {}

  // Waits for a photo still being fetched (it writes the cache the client shares).
  ~SessionSync();

  // True when the view changed. Throws inkwire::Error if an asset cannot be fetched.
  bool poll();
  // True while a product's photo is being fetched.
  bool fetching() const { return photo_.valid(); }
  SessionView& view() { return view_; }
  // A call's sound, on this client's clock: what is due up to `until` (CallAudio::take).
  CallAudio& audio() { return audio_; }
  const protocol::Snapshot& state() const { return state_; }

 private:
  SessionClient& client_;
  AssetCache& cache_;
  SessionView view_;
  protocol::Snapshot state_;
  std::vector<protocol::AssetAnnounce> fetched_;
  std::vector<std::filesystem::path> files_;
  uint64_t seen_ = ~uint64_t(0);

  // A product's photo being fetched: which sample at which level, the asset it was, and the
  // image made of it.
  struct FetchedPhoto {
    TurntableView::PhotoFetch which;
    protocol::AssetAnnounce photo;
    Image image;
  };
  std::future<FetchedPhoto> photo_;

  // Calls: members' photo and landmarks files, and faces waiting for their moment (the voice's).
  bool poll_call();
  protocol::Roster roster_;
  std::map<uint16_t, std::vector<std::filesystem::path>> member_files_;
  std::deque<protocol::MemberLayers> faces_waiting_;
  CallAudio audio_{std::chrono::steady_clock::now()};
  void fetch_photo(TurntableView::PhotoFetch which);
  // Hands a fetched photo to the view; rethrows the error that stopped its fetch.
  bool take_photo(TurntableView& product);
};

}  // namespace inkwire
