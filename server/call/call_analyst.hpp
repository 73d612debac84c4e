#pragma once
// Face analysis for calls (SPEC F8), on a thread of its own so the I/O thread keeps serving:
// members' neutral photos (the face and its 68 landmarks) and their face pictures (landmarks in
// the publisher's frame, the expression against the member's neutral face, head pose). Pictures
// come as JPEG crops or as VP8 face video (SPEC F17). Each member has one crop waiting at most:
// a newer crop replaces it; video frames all wait, since each needs the one before, and are
// decoded together, the newest picture analysed (analysis keeps up with the newest picture,
// never with a backlog). Results are handed to `done` on the analyst's thread; the server posts
// them to its I/O thread. Camera pictures live in memory only.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>

#include "common/face/face_shape.hpp"
#include "common/image.hpp"
#include "protocol/messages.hpp"
#include "server/call/face_video_decoder.hpp"
#include "server/face/face_analyzer.hpp"

namespace inkwire::server {

inline constexpr float kRegionMargin = 1.8f;  // the next crop: the face's landmarks' box grown this much about its centre
inline constexpr float kSureYaw = 30;         // degrees
inline constexpr float kSureEyes = 20;        // pixels between the eyes in the picture read

// JPEG files start with SOI and a marker: anything else is refused before it is decoded.
bool looks_like_jpeg(const protocol::Bytes& bytes);

// How the analyst reads faces, as functions so that inkwire-eval reads photos the same way.
// A member's neutral photo: the detector at the photo's scale, the largest face's landmarks.
std::optional<FaceLandmarks> photo_landmarks(FaceAnalyzer& analyzer, const Image& photo);
// A face picture (a crop or a video frame) as the analyst looks at it: scaled up to 200 px when
// smaller.
Image looked_at(const Image& picture);
// The face in such a picture when it is not tracked: the detector, doubled when it finds none,
// and the largest face's box and landmarks.
struct FoundFace {
  FaceBox box;
  FaceLandmarks landmarks;
};
std::optional<FoundFace> find_face(FaceAnalyzer& analyzer, const Image& picture);

// Which member of which session a job is for.
struct MemberKey {
  std::string session;
  uint16_t member = 0;
  auto operator<=>(const MemberKey&) const = default;
};

struct PhotoAnalysed {
  MemberKey who;
  std::string error;        // empty when the face was found
  protocol::Bytes photo;    // the JPEG as sent
  std::string landmarks;    // its landmarks as JSON (common/face/landmarks_file.hpp)
};

struct CropAnalysed {
  MemberKey who;
  uint32_t time_ms = 0;
  double analysis_ms = 0;             // decoding and finding the face took this long (server CPU per publisher)
  std::string error;                  // the crop could not be read (not a JPEG, too large, video that failed)
  int frames_dropped = 0;             // video frames that could not be decoded (the first one's reason in `error`)
  bool key_frame_wanted = false;      // the member's video waits for a key frame: ask for one
  std::optional<protocol::FaceRegion> region;  // where to crop next, for the publisher (none: nothing was analysed)
  std::optional<protocol::MemberLayers> face;  // what to send the others, when it changed (or every two seconds)
  // Whether the camera's mouth can be trusted: a head turned past kSureYaw hides a mouth corner,
  // and a face under kSureEyes pixels between the eyes shows its lips in a few blurred pixels.
  // When not, the voice's mouth goes over the camera's face (SPEC F21).
  bool mouth_sure = true;
};

class CallAnalyst {
 public:
  using Result = std::variant<PhotoAnalysed, CropAnalysed>;
  // `model`: dlib's 68-point model, loaded on the analyst's thread when the first job comes.
  explicit CallAnalyst(std::function<void(Result)> done, std::string model = "");
  ~CallAnalyst();  // finishes the job in hand, drops the rest
  CallAnalyst(const CallAnalyst&) = delete;
  CallAnalyst& operator=(const CallAnalyst&) = delete;

  void photo(const MemberKey& who, protocol::Bytes jpeg);
  void crop(const MemberKey& who, protocol::FaceCrop crop);
  // False when the frame was dropped: a frame before it was lost (the analyst fell so far behind
  // that the member's waiting frames went, or video_lost) and until a key frame comes the rest
  // cannot be decoded (ask for one).
  bool video(const MemberKey& who, protocol::FaceVideo frame);
  // A frame of the member's was refused before it got here (too frequent, too large): the rest
  // cannot be decoded without it, so they are dropped unread until a key frame (ask for one).
  void video_lost(const MemberKey& who);
  // The member left: its waiting crop and its calibration go.
  void forget(const MemberKey& who);

 private:
  struct Member;
  void run();
  PhotoAnalysed analyse_photo(const MemberKey& who, protocol::Bytes jpeg);
  struct Picture;
  CropAnalysed analyse_crop(const MemberKey& who, const protocol::FaceCrop& crop);
  CropAnalysed analyse_video(const MemberKey& who, std::deque<protocol::FaceVideo> frames);
  void analyse_picture(const MemberKey& who, const Picture& picture, CropAnalysed& out);

  std::function<void(Result)> done_;
  std::string model_;
  struct Models;
  std::unique_ptr<Models> models_;  // on the analyst's thread only

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::pair<MemberKey, protocol::Bytes>> photos_;
  std::map<MemberKey, protocol::FaceCrop> crops_;  // the newest waiting crop per member
  std::map<MemberKey, std::deque<protocol::FaceVideo>> videos_;  // every waiting video frame per member
  std::map<MemberKey, std::shared_ptr<FaceVideoDecoder>> decoders_;  // used on the analyst's thread only
  std::map<MemberKey, bool> awaiting_key_;  // frames were dropped unread: only a key frame is taken
  MemberKey last_served_;  // whose picture was analysed last: the next member takes its turn
  std::map<MemberKey, std::unique_ptr<Member>> members_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace inkwire::server
