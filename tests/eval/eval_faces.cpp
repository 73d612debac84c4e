#include "eval_faces.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>

#include <glm/glm.hpp>

#include "client/call/face_crop.hpp"
#include "common/error.hpp"
#include "common/face/expression_templates.hpp"
#include "common/image.hpp"
#include "server/call/call_analyst.hpp"
#include "server/face/expression_selector.hpp"
#include "server/face/face_analyzer.hpp"
#include "server/face/face_reader.hpp"
#include "common/face/face_layers.hpp"

namespace inkwire::eval {
namespace fs = std::filesystem;
namespace {

// Landmark i's partner across the face's vertical axis (iBUG 68-point order).
constexpr std::array<int, kFaceLandmarks> kMirror = {
    16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0, 26, 25, 24, 23, 22, 21, 20, 19, 18, 17,
    27, 28, 29, 30, 35, 34, 33, 32, 31, 45, 44, 43, 42, 47, 46, 39, 38, 37, 36, 41, 40,
    54, 53, 52, 51, 50, 49, 48, 59, 58, 57, 56, 55, 64, 63, 62, 61, 60, 67, 66, 65};

FaceLandmarks mirrored(const FaceLandmarks& offsets) {
  FaceLandmarks out;
  for (size_t i = 0; i < out.size(); ++i) out[i] = {-offsets[size_t(kMirror[i])].x, offsets[size_t(kMirror[i])].y};
  return out;
}

// The labels the selector is scored on, with the codes that count as each.
const std::vector<std::string> kLabels = {"normal", "happy", "surprised", "sleepy", "wink", "sad"};

std::string label_of(Expression e) {
  switch (e) {
    case Expression::Neutral: return "normal";
    case Expression::Smile:
    case Expression::Laugh: return "happy";
    case Expression::Surprise: return "surprised";
    case Expression::EyesClosed: return "sleepy";
    case Expression::WinkLeft:
    case Expression::WinkRight: return "wink";
    case Expression::Sad: return "sad";
    default: return name_of(e);
  }
}

struct Photo {
  int subject = 0;
  std::string label;
  fs::path file;
};

std::pair<int, int> subject_range(const std::string& text) {
  if (text.empty()) return {0, 99};
  int first = 0, last = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%d-%d%c", &first, &last, &extra) == 2 && first <= last) return {first, last};
  if (std::sscanf(text.c_str(), "%d%c", &first, &extra) == 1) return {first, first};
  throw Error("--subjects '" + text + "' is not N or N-M");
}

// subjectNN_label.png files of the wanted subjects, by subject then label.
std::map<int, std::map<std::string, fs::path>> find_photos(const FacesOptions& options) {
  if (!fs::is_directory(options.dataset)) throw Error("faces: '" + options.dataset.string() + "' is not a folder");
  const auto [first, last] = subject_range(options.subjects);
  const std::regex name(R"(subject(\d+)_([a-z]+)\.(png|jpg|gif|pgm))", std::regex::icase);
  std::map<int, std::map<std::string, fs::path>> photos;
  for (const auto& entry : fs::directory_iterator(options.dataset)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, m, name)) continue;
    const int subject = std::stoi(m[1]);
    if (subject >= first && subject <= last) photos[subject][m[2]] = entry.path();
  }
  if (photos.empty()) throw Error("faces: no subjectNN_label images for subjects " + options.subjects + " in " + options.dataset.string());
  return photos;
}

// Yale faces are small (about 100 px across): detect on the full frame, upsampled once if needed.
std::optional<FaceLandmarks> landmarks_of(FaceAnalyzer& analyzer, FaceAnalyzer& upsampled, const fs::path& file) {
  const Image image = load_image(file);
  analyzer.reset();
  if (auto a = analyzer.analyse(image)) return a->landmarks;
  upsampled.reset();
  if (auto a = upsampled.analyse(image)) return a->landmarks;
  return std::nullopt;
}

// The photo as a call's face pictures show it, framed a few pixels otherwise each time: the
// square about the face (its landmarks' box grown by the analyst's margin) moved by each of
// kFramingShifts, kept in the frame, scaled to the face video's side, and read as the analyst
// reads a picture it does not track; each framing's features.
constexpr std::array<std::array<int, 2>, 15> kFramingShifts = {{{-8, -16}, {0, -16}, {8, -16}, {-8, -8}, {0, -8}, {8, -8}, {-8, 0}, {0, 0},
                                                                {8, 0}, {-8, 8}, {0, 8}, {8, 8}, {-8, 16}, {0, 16}, {8, 16}}};

std::vector<FaceFeatures> framed_features(FaceAnalyzer& analyzer, const Image& photo, const FaceLandmarks& points) {
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (const glm::vec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const glm::vec2 centre = 0.5f * (lo + hi);
  const int side = std::min({int(std::max(hi.x - lo.x, hi.y - lo.y) * server::kRegionMargin), photo.width, photo.height});
  std::vector<FaceFeatures> out;
  for (const auto& [dx, dy] : kFramingShifts) {
    const int x = std::clamp(int(centre.x) - side / 2 + dx, 0, photo.width - side), y = std::clamp(int(centre.y) - side / 2 + dy, 0, photo.height - side);
    const Image picture = server::looked_at(resized(cropped(photo, x, y, side, side), kFaceVideoSide, kFaceVideoSide));
    if (const auto face = server::find_face(analyzer, picture)) out.push_back(measure_features(face->landmarks, &picture));
  }
  return out;
}

FaceAnalyzerOptions still_options(int upsample) { return {.detect_every = 1, .detect_width = 0, .upsample = upsample}; }

nlohmann::json features_json(const FaceFeatures& f) {
  return {{"brow_raise", {f.brow_raise_left, f.brow_raise_right}}, {"eye_open", {f.eye_open_left, f.eye_open_right}},
          {"mouth_open", f.mouth_open}, {"mouth_width", f.mouth_width}, {"corner_lift", f.corner_lift},
          {"jaw_drop", f.jaw_drop}, {"brow_inner_raise", f.brow_inner_raise}, {"eye_shade", {f.eye_shade_left, f.eye_shade_right}}};
}

}  // namespace

nlohmann::json run_faces(const FacesOptions& options) {
  const auto photos = find_photos(options);
  FaceAnalyzer analyzer(still_options(0)), upsampled(still_options(1));
  nlohmann::json per_label = nlohmann::json::object(), confusion = nlohmann::json::object(), details = nlohmann::json::array();
  int images = 0, correct = 0, no_face = 0, no_neutral = 0;
  // Each layer on its own (SPEC F21), as a call's reader (server/face/face_reader.hpp) tells a
  // still photo held for five pictures: the expression (happy: smile, surprised: surprise, sad:
  // sad, the others neutral), the eyes (sleepy: both shut, wink: one, the others both open) and
  // the mouth as drawn (open: its inner lips parted 0.1 eye distances more than the neutral
  // face's; surprised open, normal, sleepy, wink and sad not; happy faces show their teeth either
  // way and are not counted).
  std::map<std::string, std::pair<int, int>> layer_scores;  // layer -> (correct, n)
  const auto score = [&](const std::string& layer, bool right) { layer_scores[layer].first += right, ++layer_scores[layer].second; };
  int framed = 0, framed_correct = 0, framed_call = 0, framed_call_correct = 0;  // the photos as call pictures frame them
  nlohmann::json framed_per_subject = nlohmann::json::object();
  for (const auto& [subject, by_label] : photos) {
    const auto normal = by_label.find("normal");
    std::optional<FaceLandmarks> neutral_points;
    if (normal != by_label.end()) neutral_points = landmarks_of(analyzer, upsampled, normal->second);
    if (!neutral_points) {
      ++no_neutral;
      std::cerr << "faces: subject " << subject << " has no usable normal photo; skipped\n";
      continue;
    }
    const Image neutral_photo = load_image(normal->second);
    const FaceFeatures neutral = measure_features(*neutral_points, &neutral_photo);
    // A call's neutral: the photo a member joins with, read as the analyst reads it.
    std::optional<FaceFeatures> call_neutral;
    if (const auto landmarks = server::photo_landmarks(analyzer, neutral_photo)) call_neutral = measure_features(*landmarks, &neutral_photo);
    for (const std::string& label : kLabels) {
      const auto photo = by_label.find(label);
      if (photo == by_label.end()) continue;
      if (options.limit > 0 && images >= options.limit) break;
      const auto points = label == "normal" ? neutral_points : landmarks_of(analyzer, upsampled, photo->second);
      std::string chosen = "no-face";
      ExpressionState state;
      std::optional<FaceFeatures> features;
      if (points) {
        const Image image = load_image(photo->second);
        features = measure_features(*points, &image);
        state = classify(*features, neutral);
        chosen = label_of(state.expression);
        FaceReader reader;
        reader.calibrate(*neutral_points, &neutral_photo);
        for (int k = 0; k < 5; ++k) reader.read(*points, &image);
        const FaceLayers& layers = reader.state().layers;
        const Expression face = layers.expression.intensity > 0 ? layers.expression.expression : Expression::Neutral;
        const Expression wanted = label == "happy" ? Expression::Smile : label == "surprised" ? Expression::Surprise : label == "sad" ? Expression::Sad : Expression::Neutral;
        score("expression", face == wanted);
        const int shut = (layers.eye_left == 0) + (layers.eye_right == 0);
        score("eyes", shut == (label == "sleepy" ? 2 : label == "wink" ? 1 : 0));
        if (label != "happy") {
          const FaceFeatures drawn = measure_features(apply_layers(*neutral_points, shipped_templates(), layers));
          score("mouth", (drawn.mouth_open - neutral.mouth_open > 0.1f) == (label == "surprised"));
        }
        if (call_neutral) {
          const bool in_call = label == "normal" || label == "happy" || label == "surprised";  // what the call bench shows
          int right_here = 0, here = 0;
          for (const FaceFeatures& f : framed_features(analyzer, image, *points)) {
            const bool right = label_of(classify(f, *call_neutral).expression) == label;
            ++here, right_here += right;
            if (in_call) ++framed_call, framed_call_correct += right;
          }
          framed += here, framed_correct += right_here;
          auto& per = framed_per_subject[std::to_string(subject)];
          per = per.is_null() ? nlohmann::json::array({right_here, here}) : nlohmann::json::array({per[0].get<int>() + right_here, per[1].get<int>() + here});
        }
      } else {
        ++no_face;
      }
      ++images;
      const bool right = chosen == label;
      correct += right;
      auto& entry = per_label[label];
      if (entry.is_null()) entry = {{"n", 0}, {"correct", 0}};
      entry["n"] = entry["n"].get<int>() + 1;
      entry["correct"] = entry["correct"].get<int>() + int(right);
      auto& row = confusion[label];
      if (row.is_null()) row = nlohmann::json::object();
      row[chosen] = row.value(chosen, 0) + 1;
      if (options.details) {
        nlohmann::json d = {{"file", photo->second.filename().string()}, {"label", label}, {"chosen", chosen},
                            {"code", name_of(state.expression)}, {"intensity", state.intensity}};
        if (features) d["features"] = features_json(*features), d["neutral"] = features_json(neutral);
        details.push_back(d);
      }
    }
  }
  for (auto& [label, entry] : per_label.items()) entry["accuracy"] = double(entry["correct"].get<int>()) / entry["n"].get<int>();
  int core_n = 0, core_correct = 0;  // the labels the issue's target names
  for (const char* label : {"normal", "happy", "surprised", "sleepy"})
    if (per_label.contains(label)) core_n += per_label[label]["n"].get<int>(), core_correct += per_label[label]["correct"].get<int>();
  nlohmann::json out = {{"images", images},
                        {"accuracy", images ? double(correct) / images : 0.0},
                        {"accuracy_normal_happy_surprised_sleepy", core_n ? double(core_correct) / core_n : 0.0},
                        {"accuracy_framed", framed ? double(framed_correct) / framed : 0.0},
                        {"accuracy_framed_normal_happy_surprised", framed_call ? double(framed_call_correct) / framed_call : 0.0},
                        {"framed_correct_of_subject", framed_per_subject},
                        {"subjects", options.subjects.empty() ? "all" : options.subjects},
                        {"no_face", no_face},
                        {"subjects_without_neutral", no_neutral},
                        {"per_label", per_label},
                        {"per_layer", [&] {
                           nlohmann::json j = nlohmann::json::object();
                           for (const auto& [layer, cn] : layer_scores)
                             j[layer] = {{"n", cn.second}, {"correct", cn.first}, {"accuracy", cn.second ? double(cn.first) / cn.second : 0.0}};
                           return j;
                         }()},
                        {"confusion", confusion}};
  if (options.details) out["details"] = details;
  return out;
}

nlohmann::json make_face_templates(const FacesOptions& options, const fs::path& out_file) {
  const auto photos = find_photos(options);
  FaceAnalyzer analyzer(still_options(0)), upsampled(still_options(1));
  // Per label: the sum of (expression - neutral) in each subject's own neutral face frame.
  std::map<std::string, std::pair<FaceLandmarks, int>> sums;
  FaceLandmarks wink_sum{}, neutral_sum{};
  int winks = 0, neutrals = 0;
  for (const auto& [subject, by_label] : photos) {
    const auto normal = by_label.find("normal");
    if (normal == by_label.end()) continue;
    const auto neutral_points = landmarks_of(analyzer, upsampled, normal->second);
    if (!neutral_points) continue;
    const FaceFrame frame = face_frame(*neutral_points);
    const FaceLandmarks neutral = to_face(*neutral_points, frame);
    const FaceFeatures neutral_features = measure_features(*neutral_points);
    for (size_t i = 0; i < neutral.size(); ++i) neutral_sum[i] += neutral[i];
    ++neutrals;
    for (const auto& [label, file] : by_label) {
      if (label == "normal") continue;
      const auto points = landmarks_of(analyzer, upsampled, file);
      if (!points) continue;
      // In the expression photo's own frame, laid over the neutral one: head motion drops out.
      const FaceLandmarks face = to_face(*points, face_frame(*points));
      FaceLandmarks offsets;
      for (size_t i = 0; i < offsets.size(); ++i) offsets[i] = face[i] - neutral[i];
      if (label == "wink") {
        // Winks are stored as the left eye closing: a right wink is mirrored about the face's
        // vertical axis (landmark i swaps with its mirror partner).
        const FaceFeatures f = measure_features(*points);
        const bool left = f.eye_open_left / neutral_features.eye_open_left < f.eye_open_right / neutral_features.eye_open_right;
        const FaceLandmarks as_left = left ? offsets : mirrored(offsets);
        for (size_t i = 0; i < offsets.size(); ++i) wink_sum[i] += as_left[i];
        ++winks;
        continue;
      }
      auto& [sum, n] = sums[label];
      for (size_t i = 0; i < sum.size(); ++i) sum[i] += offsets[i];
      ++n;
    }
  }
  auto mean = [&](const std::string& label) {
    const auto it = sums.find(label);
    if (it == sums.end() || it->second.second == 0) throw Error("face-templates: no usable '" + label + "' photos");
    FaceLandmarks m = it->second.first;
    for (glm::vec2& p : m) p /= float(it->second.second);
    return m;
  };
  auto region = [](const FaceLandmarks& from, int first, int last, float scale = 1.0f) {
    FaceLandmarks out{};
    for (int i = first; i <= last; ++i) out[size_t(i)] = scale * from[size_t(i)];
    return out;
  };
  auto add = [](FaceLandmarks a, const FaceLandmarks& b) {
    for (size_t i = 0; i < a.size(); ++i) a[i] += b[i];
    return a;
  };

  ExpressionTemplates t;
  const std::string source = "mean over " + options.dataset.filename().string() + " subjects " + options.subjects;
  t.made = "Measured with `inkwire-eval face-templates` (dlib 68-point landmarks, each expression photo's landmarks in its "
           "own face frame minus the same subject's normal photo's) on the development subjects only; visemes, laugh "
           "and frown are composed from measured parts as each entry says.";
  auto set = [&](Expression e, const FaceLandmarks& offsets, std::string made) {
    t.offsets[size_t(e)] = offsets;
    t.made_each[size_t(e)] = std::move(made);
  };
  const FaceLandmarks happy = mean("happy"), surprised = mean("surprised"), sleepy = mean("sleepy"), sad = mean("sad");
  // Mouth and jaw parts of the measured expressions (jaw 3-13, mouth 48-67), brows (17-26).
  const FaceLandmarks surprised_mouth = add(region(surprised, 3, 13), region(surprised, 48, 67));
  const FaceLandmarks happy_mouth = add(region(happy, 2, 14), region(happy, 48, 67));
  // The mean neutral face (face frame) to close lids and narrow lips against.
  FaceLandmarks mean_neutral = neutral_sum;
  for (glm::vec2& p : mean_neutral) p /= float(neutrals);
  // Closed lids by construction: dlib's model places lids of closed eyes poorly, and a mean
  // over people half-closing their eyes is half closed. The upper lid comes down 80% of the
  // gap, the lower lid up 20%, so the lids meet.
  auto close_lids = [&](FaceLandmarks offsets, int eye_first) {
    for (auto [upper, lower] : {std::pair{1, 5}, std::pair{2, 4}}) {
      const size_t u = size_t(eye_first + upper), l = size_t(eye_first + lower);
      const float gap = mean_neutral[l].y - mean_neutral[u].y;
      offsets[u] = {0, 0.8f * gap};
      offsets[l] = {0, -0.2f * gap};
    }
    return offsets;
  };
  auto keep_lids = [&](FaceLandmarks offsets, int eye_first) {
    for (int k : {1, 2, 4, 5}) offsets[size_t(eye_first + k)] = {0, 0};
    return offsets;
  };
  // Lips drawn towards (or away from) the mouth's vertical centre line by `fraction` of their distance.
  const float mouth_centre = 0.5f * (mean_neutral[48].x + mean_neutral[54].x);
  auto narrow_lips = [&](FaceLandmarks offsets, float fraction) {
    for (int i = 48; i <= 67; ++i) offsets[size_t(i)].x -= fraction * (mean_neutral[size_t(i)].x - mouth_centre);
    return offsets;
  };
  auto no_sideways = [](FaceLandmarks offsets) {  // vertical motion only (e.g. the jaw opening without the lips narrowing)
    for (glm::vec2& o : offsets) o.x = 0;
    return offsets;
  };

  set(Expression::Smile, happy, "happy: " + source);
  set(Expression::Surprise, surprised, "surprised: " + source);
  set(Expression::EyesClosed, close_lids(close_lids(sleepy, 36), 42), "sleepy: " + source + "; lids then closed (upper 80%, lower 20% of the neutral gap)");
  set(Expression::Sad, sad, "sad: " + source + " (subtle: the photographed sad faces are)");
  if (winks > 0) {
    FaceLandmarks left = wink_sum;
    for (glm::vec2& p : left) p /= float(winks);
    left = keep_lids(close_lids(left, 36), 42);
    set(Expression::WinkLeft, left, "wink: " + source + ", right winks mirrored; left lids then closed, right lids kept open");
    set(Expression::WinkRight, mirrored(left), "wink-left mirrored");
  }
  const FaceLandmarks opening = no_sideways(surprised_mouth);
  set(Expression::Laugh, add(happy, region(opening, 0, 67, 0.6f)), "smile plus 0.6 x the surprised mouth and jaw opening (vertical part)");
  set(Expression::Frown, region(surprised, 17, 26, -0.6f), "-0.6 x the surprised brows (lowered brows)");
  set(Expression::VisemeOpen, opening, "the surprised mouth and jaw opening alone, vertical part");
  set(Expression::VisemeWide, add(region(happy_mouth, 0, 67, 0.3f), region(opening, 0, 67, 0.05f)),
      "0.3 x the smile's mouth plus 0.05 x the surprised opening (spread, slightly open lips)");
  set(Expression::VisemeRound, narrow_lips(region(opening, 0, 67, 0.6f), 0.25f),
      "0.6 x the surprised opening with the lips drawn 25% towards the mouth centre");
  set(Expression::VisemeClosed, narrow_lips(region(opening, 48, 67, -0.1f), 0.05f),
      "lips pressed: -0.1 x the surprised opening, 5% narrower");
  std::ofstream out(out_file);
  out << templates_to_json(t) << "\n";
  if (!out) throw Error("cannot write " + out_file.string());
  parse_templates(templates_to_json(t));  // what was written must load
  return {{"templates", out_file.string()}, {"winks", winks}};
}

}  // namespace inkwire::eval
