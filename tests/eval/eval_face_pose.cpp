#include "eval_face_pose.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <optional>
#include <regex>

#include <opencv2/imgproc.hpp>

#include "client/gl/context.hpp"
#include "client/gl/canvas.hpp"
#include "client/render/face/conference_view.hpp"
#include "client/render/face/face_reconstructor.hpp"
#include "common/error.hpp"
#include "common/image.hpp"
#include "common/video_source.hpp"
#include "protocol/face_versions.hpp"
#include "server/call/call_analyst.hpp"
#include "server/face/face_analyzer.hpp"
#include "server/face/face_reader.hpp"
#include "server/face/head_pose.hpp"
#include "server/face/expression_stream.hpp"
#include "server/face/layers_stream.hpp"

namespace inkwire::eval {
namespace fs = std::filesystem;
namespace {

constexpr float kTilted = 8;  // degrees of roll past which a head counts as tilted (the issue's cut)

// One frame: what the sender's camera showed, read, and what each receiver drew, read again.
struct Frame {
  int index = 0;
  HeadPose sender;
  float turn_sender = 0;
  struct Drawn {
    bool found = false;
    HeadPose pose;
    float nme = 0, turn = 0;
  } before, now;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t n = a.size();
  if (n < 3) return 0;
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / double(n), mb = std::accumulate(b.begin(), b.end(), 0.0) / double(n);
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < n; ++i) ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma), bb += (b[i] - mb) * (b[i] - mb);
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 0;
}

double spread(const std::vector<double>& v) {
  if (v.empty()) return 0;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

// The nose tip's place between the eyes: its x in the face frame (eye distances from their middle).
float turn_reading(const FaceLandmarks& p) { return face_frame(p).to_face(p[face_index::kNoseTip]).x; }

// The landmarks' error of `drawn` against `seen` over the outer eye corners' distance, the drawn
// face moved and scaled (not turned) onto the sender's: a call sends no place in the frame.
float nme(const FaceLandmarks& drawn, const FaceLandmarks& seen) {
  glm::vec2 cd(0), cs(0);
  for (size_t i = 0; i < drawn.size(); ++i) cd += drawn[i] / float(kFaceLandmarks), cs += seen[i] / float(kFaceLandmarks);
  float rd = 0, rs = 0;
  for (size_t i = 0; i < drawn.size(); ++i) rd += glm::length(drawn[i] - cd), rs += glm::length(seen[i] - cs);
  const float scale = rd > 0 ? rs / rd : 1, corners = glm::distance(seen[36], seen[45]);
  float sum = 0;
  for (size_t i = 0; i < drawn.size(); ++i) sum += glm::length((drawn[i] - cd) * scale - (seen[i] - cs));
  return sum / float(kFaceLandmarks) / std::max(corners, 1.0f);
}

float angle_error(float a, float b) { return std::abs(std::remainder(a - b, 360.0f)); }

// The largest face of a picture as the call's analyst finds one it does not track, in its pixels.
std::optional<FaceLandmarks> landmarks_of(FaceAnalyzer& analyzer, const Image& picture) {
  const Image looked = server::looked_at(picture);
  const auto found = server::find_face(analyzer, looked);
  if (!found) return std::nullopt;
  FaceLandmarks out = found->landmarks;
  const float back = float(picture.width) / float(looked.width);
  for (glm::vec2& p : out) p *= back;
  return out;
}

// The sender's member: a neutral photo, the server's reading, what the call sends of it, and two
// receivers drawing that as the call's clients do (tweened over 100 ms, at the frames' times):
// before (the single code a server of before poses sent, on a change or every two seconds; no
// pose) and now (member-layers as the call's stream sends them).
// With pictures, the face of now is also drawn in the drawn styles, comic and painterly, as a
// call's tile draws it (ConferenceView, each frame: a painting builds up over frames).
class Member {
 public:
  Member(const Image& neutral, const FaceLandmarks& landmarks, bool styled)
      : neutral_(landmarks), before_(neutral, landmarks), now_(neutral, landmarks) {
    reader_.calibrate(landmarks, &neutral);
    if (!styled) return;
    for (const char* style : {"comic", "painterly"}) {
      styled_.push_back(std::make_unique<ConferenceView>(neutral, landmarks));
      styled_.back()->set_style(style, {});
    }
    canvas_.emplace(neutral.width, neutral.height);
  }
  const FaceLandmarks& neutral() const { return neutral_; }

  // Reads the sender's frame (shown at `seconds`) as a call's analyst does; draws it both ways;
  // reads the drawings.
  Frame compare(FaceAnalyzer& analyzer, const Image& frame, const FaceLandmarks& seen, int index, double seconds, std::vector<Image>* drawn_out) {
    Frame out{.index = index, .sender = head_pose(seen, neutral_), .turn_sender = turn_reading(seen)};
    const FaceState& read = reader_.read(seen, &frame);
    if (const auto code = single_.next(reader_.expression(), seconds))
      if (const auto state = protocol::expression_state(*code)) before_.set_expression(*state, seconds);
    if (const auto sent = layers_.next(read, seconds, 1, uint32_t(seconds * 1000.0))) {
      now_.set_face(protocol::face_state_of(*sent), seconds);
      for (auto& view : styled_) view->set_face(protocol::face_state_of(*sent));
    }
    for (const bool with_pose : {false, true}) {
      FaceReconstructor& receiver = with_pose ? now_ : before_;
      Frame::Drawn& d = with_pose ? out.now : out.before;
      // Drawn once a change of this moment has tweened in (the receiver's 100 ms): the face the
      // others see of it; a change the stream holds back (its rate) still shows the last one sent.
      receiver.render(seconds + 0.1);
      const Image drawn = receiver.read();
      if (drawn_out) drawn_out->push_back(drawn);
      const auto landmarks = landmarks_of(analyzer, drawn);
      if (landmarks) d = {.found = true, .pose = head_pose(*landmarks, neutral_), .nme = nme(*landmarks, seen), .turn = turn_reading(*landmarks)};
    }
    for (auto& view : styled_) {
      const FramebufferBinding restore;
      canvas_->bind();
      view->draw(canvas_->size(), seconds);  // a view starts its tween at the frame it draws next
      view->draw(canvas_->size(), seconds + 0.1);
      if (drawn_out) drawn_out->push_back(canvas_->read());
    }
    return out;
  }

 private:
  FaceLandmarks neutral_;
  FaceReader reader_;
  ExpressionStream single_{2.0};
  LayersStream layers_{2.0};
  FaceReconstructor before_, now_;
  std::vector<std::unique_ptr<ConferenceView>> styled_;
  std::optional<Canvas> canvas_;
};

// The figures of a set of frames: before (the one code, no pose) and now.
nlohmann::json figures(const std::vector<Frame>& frames) {
  nlohmann::json out = nlohmann::json::object();
  for (const bool now : {false, true}) {
    std::vector<double> roll, roll_tilted, yaw, pitch, error_nme, turn_sender, turn_drawn;
    int found = 0;
    for (const Frame& f : frames) {
      const Frame::Drawn& d = now ? f.now : f.before;
      if (!d.found) continue;
      ++found;
      roll.push_back(angle_error(d.pose.roll, f.sender.roll));
      if (std::abs(f.sender.roll) > kTilted) roll_tilted.push_back(roll.back());
      yaw.push_back(angle_error(d.pose.yaw, f.sender.yaw));
      pitch.push_back(angle_error(d.pose.pitch, f.sender.pitch));
      error_nme.push_back(d.nme);
      turn_sender.push_back(f.turn_sender);
      turn_drawn.push_back(d.turn);
    }
    out[now ? "now" : "before"] = {{"drawn_faces_found", found},
                                   {"roll_error_deg_median", median(roll)},
                                   {"roll_error_deg_median_tilted", median(roll_tilted)},
                                   {"tilted_frames", roll_tilted.size()},
                                   {"yaw_error_deg_median", median(yaw)},
                                   {"pitch_error_deg_median", median(pitch)},
                                   {"nme_median", median(error_nme)},
                                   {"turn_correlation", correlation(turn_sender, turn_drawn)},
                                   {"turn_range_drawn_over_sender", spread(turn_sender) > 0 ? spread(turn_drawn) / spread(turn_sender) : 0.0}};
  }
  out["frames"] = frames.size();
  std::vector<double> rolls, yaws, pitches;
  for (const Frame& f : frames) rolls.push_back(f.sender.roll), yaws.push_back(f.sender.yaw), pitches.push_back(f.sender.pitch);
  out["sender_range_deg"] = {{"yaw", spread(yaws)}, {"pitch", spread(pitches)}, {"roll", spread(rolls)}};
  return out;
}

void sheet(const fs::path& dir, const std::string& name, const Image& sender, const std::vector<Image>& drawn) {
  if (dir.empty() || drawn.size() != 4) return;
  fs::create_directories(dir);
  const auto fit = [](const Image& i) { return resized(i, int(std::lround(240.0 * i.width / i.height)) & ~1, 240); };
  save_image(side_by_side({fit(sender), fit(drawn[0]), fit(drawn[1]), fit(drawn[2]), fit(drawn[3])},
                          {"sender", "before (one code, no pose)", "now (pose and layers)", "now, comic", "now, painterly"}),
             dir / (name + ".png"), false);
}

// A clip cut into tracks of one face each.
nlohmann::json run_clip(const FacePoseOptions& o, FaceAnalyzer& analyzer) {
  VideoSource source(o.clip);
  std::optional<Member> member;
  std::optional<FaceLandmarks> last;
  std::vector<std::vector<Frame>> tracks;
  nlohmann::json track_list = nlohmann::json::array();
  int frames = 0, with_face = 0;
  std::vector<int> faceless;
  Image previous_grey;
  for (std::optional<Image> frame = source.next(); frame && (o.limit == 0 || frames < o.limit); frame = source.next(), ++frames) {
    // A cut: the picture changes as a whole (mean grey difference on a 64-wide copy).
    const Image small = resized(*frame, 64, std::max(1, 64 * frame->height / frame->width));
    bool cut = false;
    if (!previous_grey.empty() && previous_grey.pixels.size() == small.pixels.size()) {
      double difference = 0;
      for (size_t i = 0; i < small.pixels.size(); i += 4) difference += std::abs(int(small.pixels[i + 1]) - int(previous_grey.pixels[i + 1]));
      cut = difference / double(small.pixels.size() / 4) > 25.0;
    }
    previous_grey = small;
    const auto seen = landmarks_of(analyzer, *frame);
    if (!seen) {
      faceless.push_back(frames);
      last.reset();
      member.reset();
      continue;
    }
    ++with_face;
    // A new track: after a cut, a frame without a face, or a face that jumped (moved more than its
    // eye distance or changed size by a third).
    const FaceFrame here = face_frame(*seen);
    bool jumped = !last;
    if (last) {
      const FaceFrame before = face_frame(*last);
      jumped = glm::distance(here.origin, before.origin) > before.scale || std::abs(here.scale / before.scale - 1.0f) > 0.33f;
    }
    last = seen;
    if (cut || jumped || !member) {
      member.emplace(*frame, *seen, !o.images_dir.empty());
      tracks.emplace_back();
      track_list.push_back({{"first_frame", frames}, {"frames", 0}});
    }
    const bool picture = !o.images_dir.empty() && frames % 15 == 0;
    std::vector<Image> drawn;
    tracks.back().push_back(member->compare(analyzer, *frame, *seen, frames, frames / source.fps(), picture ? &drawn : nullptr));
    track_list.back()["frames"] = tracks.back().size();
    if (picture) sheet(o.images_dir, "clip-" + std::to_string(1000 + frames).substr(1), *frame, drawn);
    if (frames % 25 == 0) std::cerr << "face-pose: frame " << frames << ", " << tracks.size() << " tracks\n";
  }
  std::vector<Frame> all;
  for (const auto& t : tracks) all.insert(all.end(), t.begin(), t.end());
  nlohmann::json out = {{"clip", o.clip}, {"frames", frames}, {"frames_with_face", with_face}, {"tracks", track_list}, {"all", figures(all)}};
  // Ranges of frames without a face, as the detector saw them.
  std::string ranges;
  for (size_t i = 0; i < faceless.size();) {
    size_t j = i;
    while (j + 1 < faceless.size() && faceless[j + 1] == faceless[j] + 1) ++j;
    ranges += (ranges.empty() ? "" : ", ") + std::to_string(faceless[i]) + (j > i ? "-" + std::to_string(faceless[j]) : "");
    i = j + 1;
  }
  out["frames_without_face"] = ranges;
  // Per track of at least 20 frames, and the last such (the clip's last shot).
  nlohmann::json per_track = nlohmann::json::array();
  for (size_t k = 0; k < tracks.size(); ++k)
    if (tracks[k].size() >= 20) {
      per_track.push_back(figures(tracks[k]));
      per_track.back()["first_frame"] = tracks[k].front().index;
    }
  out["tracks_of_20_frames_or_more"] = per_track;
  if (!per_track.empty()) {
    out["last_shot"] = per_track.back();
    // Its frames one by one: the turn's reading and the roll, the sender's and each drawing's.
    nlohmann::json frames_json = nlohmann::json::array();
    for (const auto& t : tracks)
      if (t.size() >= 20 && t.front().index == per_track.back()["first_frame"].get<int>())
        for (const Frame& f : t)
          frames_json.push_back({{"frame", f.index}, {"turn", {f.turn_sender, f.before.found ? f.before.turn : NAN, f.now.found ? f.now.turn : NAN}},
                                 {"yaw", {f.sender.yaw, f.now.pose.yaw}}, {"roll", {f.sender.roll, f.now.pose.roll}}});
    out["last_shot"]["per_frame"] = frames_json;
  }
  return out;
}

// Yale faces turned (and moved) in the picture: roll with a known answer.
nlohmann::json run_yale(const FacePoseOptions& o, FaceAnalyzer& analyzer) {
  const std::regex name(R"(subject(\d+)_normal\.(png|jpg|gif|pgm))", std::regex::icase);
  std::vector<fs::path> photos;
  for (const auto& e : fs::directory_iterator(o.yale))
    if (std::regex_match(e.path().filename().string(), name)) photos.push_back(e.path());
  std::sort(photos.begin(), photos.end());
  if (photos.empty()) throw Error("face-pose: no subjectNN_normal photos in " + o.yale.string());
  std::vector<Frame> frames;
  std::vector<double> truth_error_before, truth_error_now;
  int subjects = 0, missed = 0;
  for (const fs::path& file : photos) {
    const Image photo = load_image(file);
    const auto neutral = landmarks_of(analyzer, photo);
    if (!neutral) {
      std::cerr << "face-pose: no face in " << file.filename() << "; skipped\n";
      continue;
    }
    ++subjects;
    Member member(photo, *neutral, !o.images_dir.empty());
    int k = 0;
    for (const float roll : {-30.0f, -20.0f, -10.0f, 0.0f, 10.0f, 20.0f, 30.0f}) {
      // The photo turned about its face's middle and moved a little, its edges carried on.
      const glm::vec2 centre = face_frame(*neutral).origin;
      cv::Mat in(photo.height, photo.width, CV_8UC4, const_cast<uint8_t*>(photo.pixels.data())), out;
      cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(centre.x, centre.y), -roll, 1.0);  // OpenCV turns counter-clockwise on screen
      m.at<double>(0, 2) += 0.4 * roll, m.at<double>(1, 2) += 6.0;
      cv::warpAffine(in, out, m, in.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
      Image turned(photo.width, photo.height);
      std::copy(out.data, out.data + turned.pixels.size(), turned.pixels.begin());
      const auto seen = landmarks_of(analyzer, turned);
      if (!seen) {
        ++missed;
        continue;
      }
      std::vector<Image> drawn;
      const bool picture = !o.images_dir.empty() && (roll == 20.0f || roll == -30.0f);
      // A still each second: the tween long settled.
      Frame f = member.compare(analyzer, turned, *seen, k, k + 1.0, picture ? &drawn : nullptr);
      ++k;
      if (picture) sheet(o.images_dir, "yale-" + file.stem().string() + "-roll" + std::to_string(int(roll)), turned, drawn);
      if (f.before.found) truth_error_before.push_back(angle_error(f.before.pose.roll, roll));
      if (f.now.found) truth_error_now.push_back(angle_error(f.now.pose.roll, roll));
      frames.push_back(f);
    }
  }
  nlohmann::json out = {{"subjects", subjects}, {"frames_without_face", missed}, {"all", figures(frames)}};
  out["roll_error_deg_median_against_truth"] = {{"before", median(truth_error_before)}, {"now", median(truth_error_now)}};
  return out;
}

}  // namespace

nlohmann::json read_head_pose(const fs::path& neutral, const fs::path& picture) {
  FaceAnalyzer analyzer({.detect_every = 1, .detect_width = 0, .upsample = 0});
  const auto rest = landmarks_of(analyzer, load_image(neutral));
  if (!rest) throw Error("head-pose: no face in " + neutral.string());
  const auto seen = landmarks_of(analyzer, load_image(picture));
  if (!seen) throw Error("head-pose: no face in " + picture.string());
  const HeadPose pose = head_pose(*seen, *rest);
  return {{"yaw", pose.yaw}, {"pitch", pose.pitch}, {"roll", pose.roll}};
}

nlohmann::json run_face_pose(const FacePoseOptions& o) {
  if (o.clip.empty() && o.yale.empty()) throw Error("face-pose: give --clip, --yale or both");
  auto context = create_offscreen_context(64, 64);
  FaceAnalyzer analyzer({.detect_every = 1, .detect_width = 0, .upsample = 0});
  nlohmann::json out = nlohmann::json::object();
  if (!o.clip.empty()) out["clip"] = run_clip(o, analyzer);
  if (!o.yale.empty()) out["yale_rolled"] = run_yale(o, analyzer);
  return out;
}

}  // namespace inkwire::eval
