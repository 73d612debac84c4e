#include "server/call/call_analyst.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

#include "common/error.hpp"
#include "common/face/landmarks_file.hpp"
#include "common/image.hpp"
#include "common/log.hpp"
#include "server/face/face_analyzer.hpp"
#include "server/face/face_features.hpp"
#include "server/face/face_reader.hpp"
#include "server/face/layers_stream.hpp"

namespace inkwire::server {
namespace {

constexpr int kMaxDecodedSide = 1024;  // a crop is ~160 px, a whole frame 320: anything bigger is refused
constexpr int kDetectSide = 200;       // pictures are looked at this large (see looked_at)
constexpr int kDetectEvery = 2;        // crops: the detector checks the face is still there; between, it is tracked
constexpr size_t kMaxWaitingFrames = 45;  // a member's video frames waiting (3 s): past this they go, and the stream waits for a key frame

Image decode_jpeg(const protocol::Bytes& jpeg, const char* what) {
  if (!looks_like_jpeg(jpeg)) throw Error(std::string(what) + " is not a JPEG");
  Image image = load_image_from_memory(jpeg, what);
  if (image.width > kMaxDecodedSide || image.height > kMaxDecodedSide)
    throw Error(std::string(what) + " is larger than " + std::to_string(kMaxDecodedSide) + " px");
  return image;
}

const FaceBox& largest(const std::vector<FaceBox>& faces) {
  return *std::max_element(faces.begin(), faces.end(), [](const FaceBox& a, const FaceBox& b) { return a.width() < b.width(); });
}

}  // namespace

std::optional<FaceLandmarks> photo_landmarks(FaceAnalyzer& analyzer, const Image& photo) {
  const std::vector<FaceBox> faces = analyzer.detect_in_photo(photo);
  if (faces.empty()) return std::nullopt;
  return analyzer.landmarks_in(photo, largest(faces));
}

// A 160 px crop shows a face of about 90 px, near the detector's smallest (80): at 200 px it is
// found without the detector's doubling, which costs 2.5 times as much.
Image looked_at(const Image& picture) {
  if (picture.width >= kDetectSide || picture.height >= kDetectSide) return picture;
  const float up = float(kDetectSide) / float(std::max(picture.width, picture.height));
  return resized(picture, int(std::lround(float(picture.width) * up)), int(std::lround(float(picture.height) * up)));
}

std::optional<FoundFace> find_face(FaceAnalyzer& analyzer, const Image& picture) {
  std::vector<FaceBox> faces = analyzer.detect(picture);
  if (faces.empty()) faces = analyzer.detect_in_photo(picture);  // a smaller face: the detector doubled
  if (faces.empty()) return std::nullopt;
  const FaceBox& box = largest(faces);
  return FoundFace{.box = box, .landmarks = analyzer.landmarks_in(picture, box)};
}

bool looks_like_jpeg(const protocol::Bytes& b) { return b.size() >= 4 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff; }

// One picture of a member's face and where it lies in the publisher's camera frame.
struct CallAnalyst::Picture {
  uint32_t time_ms = 0;
  uint16_t frame_width = 0, frame_height = 0, x = 0, y = 0, width = 0, height = 0;
  Image image;
};

struct CallAnalyst::Models {
  FaceAnalyzer analyzer;
};

// What the analyst keeps of a member between crops.
struct CallAnalyst::Member {
  FaceReader reader;   // calibrated by the neutral photo, else by the first faces seen
  LayersStream stream{2.0};  // a face that does not change is said again every two seconds
  // Tracking between detections: where the face was in the frame, and crops since the detector ran.
  std::optional<FaceLandmarks> last_in_frame;
  int since_detection = 0;
  // The detector's box against the landmarks' bounding box at the last detection (its size in
  // their widths and heights, its centre's offset in their widths): the landmark model wants
  // the box the detector would have given.
  glm::vec2 box_scale{1}, box_offset{0};
};

CallAnalyst::CallAnalyst(std::function<void(Result)> done, std::string model)
    : done_(std::move(done)), model_(std::move(model)), thread_([this] { run(); }) {}

CallAnalyst::~CallAnalyst() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void CallAnalyst::photo(const MemberKey& who, protocol::Bytes jpeg) {
  {
    std::lock_guard lock(mutex_);
    std::erase_if(photos_, [&](const auto& p) { return p.first == who; });  // a retake replaces one not yet looked at
    photos_.emplace_back(who, std::move(jpeg));
  }
  wake_.notify_one();
}

void CallAnalyst::crop(const MemberKey& who, protocol::FaceCrop crop) {
  {
    std::lock_guard lock(mutex_);
    crops_[who] = std::move(crop);
    if (auto& member = members_[who]; !member) member = std::make_unique<Member>();
  }
  wake_.notify_one();
}

bool CallAnalyst::video(const MemberKey& who, protocol::FaceVideo frame) {
  bool kept = true;
  {
    std::lock_guard lock(mutex_);
    auto& waiting = videos_[who];
    bool& awaiting_key = awaiting_key_[who];
    if (waiting.size() >= kMaxWaitingFrames) {
      // The analyst is this far behind (its model loading, a crowd of members): what waits is
      // dropped, and what comes until a key frame could not be decoded without it.
      waiting.clear();
      awaiting_key = true;
    }
    if (awaiting_key && !frame.key) {
      kept = false;
    } else {
      awaiting_key = false;
      waiting.push_back(std::move(frame));
    }
    if (waiting.empty()) videos_.erase(who);
    if (auto& member = members_[who]; !member) member = std::make_unique<Member>();
  }
  if (kept) wake_.notify_one();
  return kept;
}

void CallAnalyst::video_lost(const MemberKey& who) {
  std::lock_guard lock(mutex_);
  awaiting_key_[who] = true;
}

void CallAnalyst::forget(const MemberKey& who) {
  std::lock_guard lock(mutex_);
  crops_.erase(who);
  videos_.erase(who);
  awaiting_key_.erase(who);
  decoders_.erase(who);
  std::erase_if(photos_, [&](const auto& p) { return p.first == who; });
  members_.erase(who);
}

void CallAnalyst::run() {
  for (;;) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return stopping_ || !photos_.empty() || !crops_.empty() || !videos_.empty(); });
    if (stopping_) return;
    std::optional<Result> result;
    try {
      if (!models_) {
        lock.unlock();
        FaceAnalyzerOptions options{.detect_every = 1, .detect_width = 0};
        if (!model_.empty()) options.model = model_;
        models_ = std::make_unique<Models>(Models{FaceAnalyzer(options)});
        lock.lock();
      }
      if (!photos_.empty()) {
        auto [who, jpeg] = std::move(photos_.front());
        photos_.pop_front();
        lock.unlock();
        result = analyse_photo(who, std::move(jpeg));
      } else {
        // Members take turns, the one after the last served first (then from the first again): a
        // member whose pictures keep coming while another's is analysed must not keep the others waiting.
        const auto turn = [&](const MemberKey& k) { return std::pair(!(last_served_ < k), k); };
        const auto next = [&](auto& waiting) {
          const auto after = waiting.upper_bound(last_served_);
          return after != waiting.end() ? after : waiting.begin();
        };
        const auto crop = next(crops_);
        const auto video = next(videos_);
        const bool crop_first = video == videos_.end() || (crop != crops_.end() && turn(crop->first) < turn(video->first));
        if (crop != crops_.end() && crop_first) {
          auto node = crops_.extract(crop);
          last_served_ = node.key();
          lock.unlock();
          result = analyse_crop(node.key(), node.mapped());
        } else {
          auto node = videos_.extract(video);
          last_served_ = node.key();
          lock.unlock();
          result = analyse_video(node.key(), std::move(node.mapped()));
        }
      }
    } catch (const std::exception& e) {
      // No model: every job says so (the server logs it once per member).
      log(LogLevel::Error, "call-analysis-failed", {{"reason", e.what()}});
      if (lock.owns_lock()) lock.unlock();
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    if (result) done_(std::move(*result));
  }
}

PhotoAnalysed CallAnalyst::analyse_photo(const MemberKey& who, protocol::Bytes jpeg) {
  PhotoAnalysed out{.who = who, .error = {}, .photo = {}, .landmarks = {}};
  try {
    const Image photo = decode_jpeg(jpeg, "neutral photo");
    const std::optional<FaceLandmarks> found = photo_landmarks(models_->analyzer, photo);
    if (!found) throw Error("no face found in your photo");
    const FaceLandmarks& landmarks = *found;
    auto member = std::make_unique<Member>();
    member->reader.calibrate(landmarks, &photo);
    {
      std::lock_guard lock(mutex_);
      members_[who] = std::move(member);  // a retake calibrates anew (a member who left meanwhile is dropped by the server)
    }
    out.photo = std::move(jpeg);
    out.landmarks = landmarks_to_json(landmarks);
  } catch (const Error& e) {
    out.error = e.what();
  }
  return out;
}

CropAnalysed CallAnalyst::analyse_crop(const MemberKey& who, const protocol::FaceCrop& crop) {
  CropAnalysed out{.who = who, .time_ms = crop.time_ms};
  try {
    const auto started = std::chrono::steady_clock::now();
    Picture picture{.time_ms = crop.time_ms, .frame_width = crop.frame_width, .frame_height = crop.frame_height, .x = crop.x, .y = crop.y,
                    .width = crop.width, .height = crop.height, .image = decode_jpeg(crop.jpeg, "face crop")};
    analyse_picture(who, picture, out);
    out.analysis_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  } catch (const Error& e) {
    out.error = e.what();
  }
  return out;
}

// Every frame is decoded, in order (each needs the one before); the newest picture is analysed.
// A frame that fails is counted with its reason and the stream waits for a key frame.
CropAnalysed CallAnalyst::analyse_video(const MemberKey& who, std::deque<protocol::FaceVideo> frames) {
  CropAnalysed out{.who = who, .time_ms = frames.back().time_ms};
  const auto started = std::chrono::steady_clock::now();
  std::shared_ptr<FaceVideoDecoder> decoder;
  {
    std::lock_guard lock(mutex_);
    if (!members_.count(who)) return out;  // left meanwhile
    auto& d = decoders_[who];
    if (!d) d = std::make_shared<FaceVideoDecoder>();
    decoder = d;
  }
  std::optional<Picture> newest;
  for (const protocol::FaceVideo& f : frames) {
    try {
      newest = Picture{.time_ms = f.time_ms, .frame_width = f.frame_width, .frame_height = f.frame_height, .x = f.x, .y = f.y,
                       .width = f.width, .height = f.height, .image = decoder->decode(f)};
    } catch (const Error& e) {
      if (out.error.empty()) out.error = e.what();
      ++out.frames_dropped;
    }
  }
  out.key_frame_wanted = decoder->waiting_for_key();
  if (!newest) return out;
  out.time_ms = newest->time_ms;
  try {
    analyse_picture(who, *newest, out);
  } catch (const Error& e) {
    if (out.error.empty()) out.error = e.what();
  }
  out.analysis_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return out;
}

void CallAnalyst::analyse_picture(const MemberKey& who, const Picture& crop, CropAnalysed& out) {
  {
    const Image image = looked_at(crop.image);
    const float sx = float(crop.width) / float(image.width), sy = float(crop.height) / float(image.height);
    // Where the face was, in this crop's pixels: the landmark model placed there directly (a
    // millisecond) instead of the detector (tens), except every kDetectEvery-th crop.
    std::optional<FaceBox> tracked;
    {
      std::lock_guard lock(mutex_);
      const auto it = members_.find(who);
      if (it == members_.end()) return;
      Member& m = *it->second;
      if (m.last_in_frame && m.since_detection + 1 < kDetectEvery) {
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const glm::vec2& p : *m.last_in_frame) lo = glm::min(lo, p), hi = glm::max(hi, p);
        // The landmarks' box in this crop's pixels, then the detector's box as it stood to it.
        const glm::vec2 a((lo.x - float(crop.x)) / sx, (lo.y - float(crop.y)) / sy), b((hi.x - float(crop.x)) / sx, (hi.y - float(crop.y)) / sy);
        const glm::vec2 size = b - a, centre = (a + b) * 0.5f + m.box_offset * size.x, half = size * m.box_scale * 0.5f;
        if (centre.x > 0 && centre.y > 0 && centre.x < float(image.width) && centre.y < float(image.height) && size.x > 16)
          tracked = FaceBox{int(centre.x - half.x), int(centre.y - half.y), int(centre.x + half.x), int(centre.y + half.y)};
      }
    }
    std::optional<FaceLandmarks> found;
    std::optional<FaceBox> detected;
    if (tracked) {
      found = models_->analyzer.landmarks_in(image, *tracked);
    } else if (const std::optional<FoundFace> face = find_face(models_->analyzer, image)) {
      detected = face->box;
      found = face->landmarks;
    }
    // The member's calibration is read and changed under the lock: forget() may end it meanwhile.
    std::lock_guard lock(mutex_);
    const auto it = members_.find(who);
    if (it == members_.end()) return;  // left meanwhile
    Member* member = it->second.get();
    member->since_detection = tracked ? member->since_detection + 1 : 0;
    if (detected && found) {
      glm::vec2 lo(1e9f), hi(-1e9f);
      for (const glm::vec2& p : *found) lo = glm::min(lo, p), hi = glm::max(hi, p);
      const glm::vec2 size = glm::max(hi - lo, glm::vec2(1));
      const glm::vec2 box_centre(float(detected->left + detected->right) * 0.5f, float(detected->top + detected->bottom) * 0.5f);
      member->box_scale = glm::vec2(float(detected->width()), float(detected->height())) / size;
      member->box_offset = (box_centre - (lo + hi) * 0.5f) / size.x;
    }
    if (!found) {
      member->reader.read(std::nullopt);
      member->last_in_frame.reset();
      out.region = protocol::FaceRegion{.found = false};
      return;
    }
    // The landmarks in the publisher's frame: the crop shows crop.width x crop.height of it.
    FaceLandmarks in_frame = *found;
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (glm::vec2& p : in_frame) {
      p = glm::vec2(float(crop.x) + p.x * sx, float(crop.y) + p.y * sy);
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    const glm::vec2 centre = (lo + hi) * 0.5f;
    const float side = std::max(hi.x - lo.x, hi.y - lo.y) * kRegionMargin;
    const float x0 = std::clamp(centre.x - side / 2, 0.0f, float(crop.frame_width - 8)), y0 = std::clamp(centre.y - side / 2, 0.0f, float(crop.frame_height - 8));
    out.region = protocol::FaceRegion{.found = true, .x = uint16_t(x0), .y = uint16_t(y0),
                                      .width = uint16_t(std::clamp(side, 8.0f, float(crop.frame_width) - x0)),
                                      .height = uint16_t(std::clamp(side, 8.0f, float(crop.frame_height) - y0))};
    member->last_in_frame = in_frame;
    // Features from the picture's landmarks (the eyes' shade is read in it), the pose from the
    // frame's (a crop at the frame's edge may be scaled unevenly).
    const FaceState& state = member->reader.read(*found, &image, &in_frame);
    out.mouth_sure = std::abs(state.pose.yaw) <= kSureYaw && face_frame(*found).scale >= kSureEyes;
    out.face = member->stream.next(state, crop.time_ms / 1000.0, who.member, crop.time_ms);
  }
}

}  // namespace inkwire::server
