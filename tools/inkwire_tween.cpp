// inkwire-tween: the tween machinery applied to pairs of images (SPEC T8, T9).
//
//   inkwire-tween morph --from A.jpg --to B.jpg --out morph.mp4 [--points pairs.json] [--sheet sheet.png]
//       Morphs between two different faces (landmarks found by the face model) or objects
//       (corresponding points given as {"pairs": [[ax, ay, bx, by], ...]} in each image's pixels).
//   inkwire-tween restore --input SRC --out restored.mp4 (--missing 10-14,30 | --keep-every 4) [--json stats.json]
//       Regenerates missing video frames by tweening between the kept frames around them, on
//       landmarks found automatically between those two frames (NCC). The frames it replaces
//       are compared with what the input had there: PSNR against holding the last kept frame
//       and against a cross-fade.
//   inkwire-tween shape --photos DIR --out DIR [--rows N] [--elevations A,B] [--step D | --arc D]
//       Finds a turntable's camera and the object's visual hull from the photos' mattes (SPEC
//       T24, T25) and writes the hull (hull.ply), every photo's depth map (depth-N.png) and
//       camera.json: focal length, each row's elevation, the axis, the angles, each photo's
//       hull IoU against its matte.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "client/gl/context.hpp"
#include "client/output/frame_writer.hpp"
#include "client/render/tween/pair_tween.hpp"
#include "common/error.hpp"
#include "common/image_metrics.hpp"
#include "common/video_source.hpp"
#include "server/face/face_analyzer.hpp"
#include "server/products/photo_keying.hpp"
#include "server/products/photo_shape.hpp"
#include "server/products/turn_angles.hpp"
#include "server/tween/landmarks.hpp"

using namespace inkwire;

namespace {

constexpr int kMaxFrames = 5000;

// ---- morph (T8) ----

struct MorphOptions {
  std::string from, to, points, out, sheet, json_path;
  int frames = 48, fps = 24;
  bool frame_faces = false;
};

// Corresponding points from a file: {"pairs": [[ax, ay, bx, by], ...]}.
std::vector<Landmark> points_from_file(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read points '" + file + "'");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("pairs") || !j["pairs"].is_array())
    throw Error("points '" + file + "': not {\"pairs\": [[ax, ay, bx, by], ...]}");
  std::vector<Landmark> pairs;
  for (const auto& p : j["pairs"]) {
    if (!p.is_array() || p.size() != 4 || !std::all_of(p.begin(), p.end(), [](const auto& v) { return v.is_number(); }))
      throw Error("points '" + file + "': pair " + std::to_string(pairs.size()) + " is not [ax, ay, bx, by]");
    pairs.push_back({.source = {p[0].get<float>(), p[1].get<float>()}, .target = {p[2].get<float>(), p[3].get<float>()}, .match = 1});
  }
  if (pairs.size() < 3 || pairs.size() > size_t(kMaxTweenPointsPerCell)) throw Error("points '" + file + "': give 3 to 4096 pairs");
  return pairs;
}

FaceLandmarks face_of(const Image& image, const std::string& name) {
  FaceAnalyzer analyzer({.detect_every = 1, .detect_width = 0, .upsample = image.width < 480 ? 1 : 0});
  const auto face = analyzer.analyse(image);
  if (!face) throw Error("no face found in '" + name + "'; give corresponding points with --points");
  return face->landmarks;
}

// A head-and-shoulders crop around a face, in inter-ocular distances from the eyes' midpoint
// (roll is ignored), kept inside the image.
struct Crop {
  int x = 0, y = 0, width = 0, height = 0;
};
Crop face_crop(const Image& image, const FaceLandmarks& face) {
  const FaceFrame frame = face_frame(face);
  const float half_width = 2.4f * frame.scale, above = 2.6f * frame.scale, below = 3.4f * frame.scale;
  Crop c;
  c.width = std::min(int(2 * half_width), image.width);
  c.height = std::min(int(above + below), image.height);
  c.x = std::clamp(int(frame.origin.x - half_width), 0, image.width - c.width);
  c.y = std::clamp(int(frame.origin.y - above), 0, image.height - c.height);
  return c;
}

int morph(const MorphOptions& o) {
  Image a = load_image(o.from);
  Image b_original = load_image(o.to);
  std::vector<Landmark> pairs;
  if (!o.points.empty()) {
    if (o.frame_faces) throw Error("--frame-faces works with face landmarks, not --points");
    pairs = points_from_file(o.points);
  } else {
    FaceLandmarks fa = face_of(a, o.from), fb = face_of(b_original, o.to);
    if (o.frame_faces) {
      // Both faces cut out at the same framing, so the morph moves features, not whole photos.
      const Crop ca = face_crop(a, fa), cb = face_crop(b_original, fb);
      a = cropped(a, ca.x, ca.y, ca.width, ca.height), b_original = cropped(b_original, cb.x, cb.y, cb.width, cb.height);
      for (glm::vec2& p : fa) p -= glm::vec2(ca.x, ca.y);
      for (glm::vec2& p : fb) p -= glm::vec2(cb.x, cb.y);
    }
    for (int i = 0; i < kFaceLandmarks; ++i) pairs.push_back({.source = fa[size_t(i)], .target = fb[size_t(i)], .match = 1});
    // The landmarks stop at the brows: points on the forehead and the top of the head (in each
    // face's frame) carry the hairline along instead of leaving two outlines cross-fading.
    const FaceFrame frame_a = face_frame(fa), frame_b = face_frame(fb);
    const auto inside = [](const glm::vec2& p, const Image& image) {
      return p.x >= 0 && p.y >= 0 && p.x < float(image.width) && p.y < float(image.height);
    };
    for (const glm::vec2 head : {glm::vec2(-1.3f, -1.5f), glm::vec2(-0.6f, -1.7f), glm::vec2(0.0f, -1.8f), glm::vec2(0.6f, -1.7f),
                                 glm::vec2(1.3f, -1.5f), glm::vec2(-1.0f, -2.5f), glm::vec2(0.0f, -2.7f), glm::vec2(1.0f, -2.5f)}) {
      const glm::vec2 pa = frame_a.to_image(head), pb = frame_b.to_image(head);
      if (inside(pa, a) && inside(pb, b_original)) pairs.push_back({.source = pa, .target = pb, .match = 1});
    }
  }
  if (a.width > kMaxTweenImageSide || a.height > kMaxTweenImageSide) throw Error("'" + o.from + "' is larger than 4095 pixels");
  // The warp needs one size: the second image is scaled to the first's, its points with it.
  const Image b = resized(b_original, a.width, a.height);
  const glm::vec2 b_scale(float(a.width) / float(b_original.width), float(a.height) / float(b_original.height));
  for (Landmark& p : pairs) {
    p.target *= b_scale;
    for (const glm::vec2& q : {p.source, p.target})
      if (!(q.x >= 0 && q.y >= 0 && q.x <= float(a.width) && q.y <= float(a.height))) throw Error("a point lies outside the images");
  }

  auto context = create_offscreen_context(64, 64);
  PairTween tween(a, b, cell_from_landmarks(pairs, 0, 1));
  FrameWriter writer(o.out, o.frames, o.fps, false);
  for (int i = 0; i < o.frames; ++i) writer.write(tween.tween(float(i) / float(std::max(o.frames - 1, 1))));
  writer.close();
  if (!o.sheet.empty()) {
    // A then the morph at quarter steps then B, and the cross-dissolve halfway for comparison.
    std::vector<Image> panels;
    for (float t : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) panels.push_back(tween.tween(t));
    panels.push_back(tween.crossfade(0.5f));
    const int height = std::min(a.height, 360), width = std::max(2, a.width * height / a.height);
    for (Image& p : panels) p = resized(p, width, height);
    save_image(side_by_side(panels, {"A", "morph 1/4", "morph 1/2", "morph 3/4", "B", "cross-fade 1/2 (for comparison)"}), o.sheet, false);
  }
  const nlohmann::json stats = {{"points", pairs.size()}, {"frames", o.frames}, {"size", {a.width, a.height}}};
  if (!o.json_path.empty()) std::ofstream(o.json_path) << stats.dump(2) << "\n";
  std::cout << stats.dump(2) << "\n";
  return 0;
}

// ---- restore (T9) ----

struct RestoreOptions {
  std::string input, out, missing, json_path, sheet;
  int keep_every = 0, landmarks = 65;
  std::vector<int> search = {40, 12};
};

// "10-14,30": frame indices.
std::set<int> parse_ranges(const std::string& text) {
  std::set<int> frames;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    int first = 0, last = 0;
    char dash = 0, extra = 0;
    const int n = std::sscanf(item.c_str(), "%d%c%d%c", &first, &dash, &last, &extra);
    if (n == 1) last = first;
    else if (n != 3 || dash != '-') throw Error("--missing item '" + item + "' is not N or N-M");
    if (first < 0 || last < first || last >= kMaxFrames) throw Error("--missing item '" + item + "' is out of range");
    for (int f = first; f <= last; ++f) frames.insert(f);
  }
  return frames;
}

int restore(const RestoreOptions& o) {
  VideoSource source(o.input);
  std::vector<Image> frames;
  while (auto frame = source.next()) {
    if (int(frames.size()) >= kMaxFrames) throw Error("the input has more than 5000 frames");
    if (!frames.empty() && (frame->width != frames[0].width || frame->height != frames[0].height)) throw Error("the input's frames differ in size");
    frames.push_back(std::move(*frame));
  }
  if (frames.size() < 3) throw Error("the input has fewer than 3 frames");
  if (frames[0].width > kMaxTweenImageSide || frames[0].height > kMaxTweenImageSide) throw Error("frames larger than 4095 pixels");
  std::set<int> missing;
  if (o.keep_every > 1) {
    for (int i = 0; i < int(frames.size()); ++i)
      if (i % o.keep_every != 0) missing.insert(i);
    // The last frames have no kept frame after them unless the last one is kept.
    for (int i = int(frames.size()) - 1; i >= 0 && missing.count(i); --i) missing.erase(i);
  } else {
    missing = parse_ranges(o.missing);
  }
  for (int f : missing) {
    if (f >= int(frames.size())) throw Error("frame " + std::to_string(f) + " is past the input's end");
    if (f == 0 || f == int(frames.size()) - 1) throw Error("frame " + std::to_string(f) + " has no kept frame on both sides");
  }

  auto context = create_offscreen_context(64, 64);
  LandmarkOptions landmark_options;
  landmark_options.count = o.landmarks;
  landmark_options.search = {o.search.at(0), o.search.at(1)};
  std::vector<Image> restored = frames;
  double sums[3] = {0, 0, 0};  // hold, cross-fade, tween
  int compared = 0, gaps = 0;
  size_t landmark_total = 0;
  std::optional<std::vector<Image>> sheet_panels;
  for (auto it = missing.begin(); it != missing.end();) {
    const int a = *it - 1;
    int b = *it;
    while (missing.count(b)) ++b;
    const std::vector<Landmark> landmarks = find_landmarks(grey_of(frames[size_t(a)]), grey_of(frames[size_t(b)]), landmark_options);
    landmark_total += landmarks.size();
    ++gaps;
    PairTween tween(frames[size_t(a)], frames[size_t(b)], cell_from_landmarks(landmarks, 0, 1));
    for (int k = a + 1; k < b; ++k) {
      const float t = float(k - a) / float(b - a);
      restored[size_t(k)] = tween.tween(t);
      const Image& hold = frames[size_t(t < 0.5f ? a : b)];
      const Image fade = tween.crossfade(t);
      sums[0] += psnr(hold, frames[size_t(k)]);
      sums[1] += psnr(fade, frames[size_t(k)]);
      sums[2] += psnr(restored[size_t(k)], frames[size_t(k)]);
      ++compared;
      if (!sheet_panels && k == (a + b) / 2) sheet_panels = std::vector<Image>{frames[size_t(k)], hold, fade, restored[size_t(k)]};
    }
    it = missing.upper_bound(b);
  }
  FrameWriter writer(o.out, int(restored.size()), int(std::lround(source.fps())), false);
  for (const Image& f : restored) writer.write(f);
  writer.close();
  if (!o.sheet.empty() && sheet_panels)
    save_image(side_by_side(*sheet_panels, {"dropped frame (truth)", "hold the nearest", "cross-fade", "tween"}), o.sheet, false);

  nlohmann::json stats = {{"frames", frames.size()}, {"regenerated", missing.size()}, {"gaps", gaps},
                          {"landmarks_per_gap", gaps ? double(landmark_total) / gaps : 0.0}};
  if (compared > 0)
    stats["psnr_against_input"] = {{"hold", sums[0] / compared}, {"crossfade", sums[1] / compared}, {"tween", sums[2] / compared}};
  if (!o.json_path.empty()) std::ofstream(o.json_path) << stats.dump(2) << "\n";
  std::cout << stats.dump(2) << "\n";
  return 0;
}

// ---- shape (T24, T25) ----

struct ShapeOptions {
  std::string photos, out;
  PhotoLayout layout;
};

int shape(ShapeOptions o) {
  o.layout.folder_calibration = false;  // a calibration in the folder is read only when --calibration names it
  PhotoFolder photos = read_photo_folder(o.photos, o.layout);
  const KeyedPhotos keyed = key_photos(photos, "auto", [](int, int, const std::string& line) { std::cout << line << "\n"; });
  if (!keyed.matted) std::cout << "silhouettes cut from the backdrops instead of mattes\n";
  // The turn and a first focal length from the corners tracked round (as add-product finds them).
  float field_of_view = kDefaultFieldOfView;
  if (photos.even_turn_assumed && photos.closed) {
    const TurnSteps steps = turn_steps_from_photos(photos);
    if (steps.fitted >= 3 && steps.uneven()) set_turn_steps(photos, steps.degrees);
    if (steps.fitted >= 3 && steps.direction_known) field_of_view = std::abs(steps.field_of_view);
  }
  std::cout << "finding the camera from " << photos.photos.size() << (keyed.matted ? " mattes (" : " silhouettes (") << photos.rows << " row" << (photos.rows > 1 ? "s" : "")
            << "), first guess: field of view " << field_of_view << " of the longer side\n";
  PhotoSilhouettes silhouettes = photo_silhouettes(photos, keyed.matted);
  const PhotoShape found = shape_from_silhouettes(photos, silhouettes, field_of_view, [](const std::string& line) { std::cout << line << "\n"; });
  write_shape(found, o.out);
  // What the hull was carved from, beside it: silhouette-N.png, the photo where its silhouette
  // is and a quarter of it elsewhere.
  for (size_t i = 0; i < silhouettes.each.size(); ++i) {
    Image picture = photos.photos[i];
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x) {
        uint8_t* p = picture.at(x, y);
        if (!silhouettes.each[i].at(x, y)) std::transform(p, p + 3, p, [](uint8_t v) { return uint8_t(v / 4); });
        p[3] = 255;
      }
    save_image(picture, std::filesystem::path(o.out) / ("silhouette-" + std::to_string(i + 1) + ".png"), false);
  }
  std::cout << shape_summary(found) << " (" << found.evaluations << " hulls carved to find the camera); written to " << o.out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"inkwire-tween: morph between two faces or objects, regenerate missing video frames by tweening, or find a turntable's shape"};
  app.require_subcommand(1);
  MorphOptions m;
  auto* morph_cmd = app.add_subcommand("morph", "morph between two different faces or objects");
  morph_cmd->add_option("--from", m.from, "first image")->required();
  morph_cmd->add_option("--to", m.to, "second image (scaled to the first's size)")->required();
  morph_cmd->add_option("--points", m.points, "corresponding points {\"pairs\": [[ax, ay, bx, by], ...]}; default: face landmarks");
  morph_cmd->add_flag("--frame-faces", m.frame_faces, "cut both photos to the same head-and-shoulders framing around their faces");
  morph_cmd->add_option("--out", m.out, "the morph (.mp4 or %04d.png)")->required();
  morph_cmd->add_option("--sheet", m.sheet, "PNG: A, the morph at 1/4, 1/2, 3/4, B, and the cross-dissolve at 1/2");
  morph_cmd->add_option("--frames", m.frames, "frames from A to B")->check(CLI::Range(2, kMaxFrames));
  morph_cmd->add_option("--fps", m.fps, "frame rate")->check(CLI::Range(1, 120));
  morph_cmd->add_option("--json", m.json_path, "write the figures here");
  RestoreOptions r;
  auto* restore_cmd = app.add_subcommand("restore", "regenerate missing video frames between kept ones");
  restore_cmd->add_option("--input", r.input, "video file, folder of images or %04d pattern")->required();
  restore_cmd->add_option("--out", r.out, "the restored video (.mp4 or %04d.png)")->required();
  auto* missing = restore_cmd->add_option("--missing", r.missing, "frames to regenerate, e.g. 10-14,30");
  auto* keep = restore_cmd->add_option("--keep-every", r.keep_every, "keep every K-th frame and regenerate the rest")->check(CLI::Range(2, 100));
  missing->excludes(keep);
  restore_cmd->add_option("--landmarks", r.landmarks, "landmarks per gap")->check(CLI::Range(3, 4096));
  restore_cmd->add_option("--search", r.search, "how far a landmark may move between the kept frames: X Y pixels")->expected(2);
  restore_cmd->add_option("--sheet", r.sheet, "PNG of the middle of the first gap: input | hold | cross-fade | tween");
  restore_cmd->add_option("--json", r.json_path, "write the figures here");
  ShapeOptions sh;
  auto* shape_cmd = app.add_subcommand("shape", "find a turntable's camera and the object's hull from its photos' silhouettes");
  shape_cmd->add_option("--photos", sh.photos, "a folder of turntable photos (as add-product reads them): mattes from a plain backdrop, else silhouettes cut from theirs")->required();
  shape_cmd->add_option("--out", sh.out, "folder for hull.ply, depth-N.png and camera.json")->required();
  shape_cmd->add_option("--calibration", sh.layout.calibration,
                        "the photos' calibration (Middlebury *_par.txt): their order and azimuths, and the camera the one found is checked "
                        "against and the hull carved under (a calibration in the folder is otherwise ignored)")
      ->check(CLI::ExistingFile);
  shape_cmd->add_option("--rows", sh.layout.rows, "rings of photos in the folder, in file-name order")->check(CLI::Range(1, 32));
  shape_cmd->add_option("--elevations", sh.layout.elevations, "first guesses of each row's elevation, degrees")->delimiter(',');
  auto* step = shape_cmd->add_option("--step", sh.layout.step_degrees, "the turn between consecutive photos, degrees");
  shape_cmd->add_option("--arc", sh.layout.arc_degrees, "the turn from a row's first photo to its last, degrees")->excludes(step);
  try {
    app.parse(argc, argv);
    if (restore_cmd->parsed() && r.missing.empty() && r.keep_every == 0) throw CLI::ValidationError("restore needs --missing or --keep-every");
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (shape_cmd->parsed()) return shape(sh);
    return morph_cmd->parsed() ? morph(m) : restore(r);
  } catch (const std::exception& e) {
    std::cerr << "inkwire-tween: " << e.what() << "\n";
    return 1;
  }
}
