// inkwire-conference: a whole low-bandwidth conference in one process, for demos and
// measurement. The speaker side (camera, video or image sequence) runs the server's face
// pipeline; what a call sends of a face (member-layers: the layers and the head's pose) goes
// through the real wire encoding and decoding; the receiver side deforms and turns the neutral
// photo (sent once) by each, and optionally paints it. Writes the side-by-side video input |
// reconstruction | painted reconstruction and the bytes sent (and what the session-wide single
// code would have cost).
//
//   inkwire-conference --input SRC --out side.mp4 [--neutral PHOTO] [--json stats.json]
//   inkwire-conference --speaker PHOTO --script smile:1,neutral:0.5 --out side.mp4 [--input-out speaker.mp4]
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/output/frame_writer.hpp"
#include "client/render/backdrop.hpp"
#include "client/render/face/face_reconstructor.hpp"
#include "client/render/painterly/video_painter.hpp"
#include "common/error.hpp"
#include "common/video_source.hpp"
#include "protocol/face_versions.hpp"
#include "protocol/framing.hpp"
#include "server/face/face_coder.hpp"

using namespace inkwire;

namespace {

struct Options {
  std::string input, neutral, speaker, script, out, input_out, json_path, paint = "impressionist";
  int fps = 0, repeat = 1, frames = 0, height = 360;
  int face = 0;  // --speaker: which face, 1 = leftmost; 0: the largest
};

// The speaker's photo framed on one face: a portrait around it (the face a third of its width),
// cut from the photo and scaled so the face is about 200 pixels wide, as a webcam would frame it.
struct FramedFace {
  Image photo;
  FaceLandmarks landmarks;
};

FramedFace frame_on_face(const Image& photo, int which) {
  FaceAnalyzer analyzer({.detect_every = 1, .detect_width = 0, .upsample = 0});
  const std::vector<FaceBox> faces = analyzer.detect_in_photo(photo);
  if (faces.empty()) throw Error("--speaker photo shows no face the detector finds (a frontal face at least ~40 pixels wide)");
  if (which > int(faces.size()))
    throw Error("--face " + std::to_string(which) + ": the photo shows " + std::to_string(faces.size()) + " faces (1 is the leftmost)");
  const FaceBox box = which > 0 ? faces[size_t(which - 1)]
                                : *std::max_element(faces.begin(), faces.end(), [](const FaceBox& a, const FaceBox& b) { return a.width() < b.width(); });
  const int side = box.width();
  const int width = std::min(photo.width, 3 * side), height = std::min(photo.height, 4 * side);
  const int cx = (box.left + box.right) / 2, cy = (box.top + box.bottom) / 2;
  const int x = std::clamp(cx - width / 2, 0, photo.width - width), y = std::clamp(cy - height * 9 / 20, 0, photo.height - height);
  Image portrait = cropped(photo, x, y, width, height);
  const double scale = 200.0 / side;
  if (scale < 1.0) portrait = resized(portrait, std::max(2, int(width * scale) & ~1), std::max(2, int(height * scale) & ~1));
  else portrait = resized(portrait, width & ~1, height & ~1);
  const double sx = double(portrait.width) / width, sy = double(portrait.height) / height;
  const FaceBox in_portrait{int((box.left - x) * sx), int((box.top - y) * sy), int((box.right - x) * sx), int((box.bottom - y) * sy)};
  return {portrait, analyzer.landmarks_in(portrait, in_portrait)};
}

struct ScriptStep {
  ExpressionState state;
  double seconds;
};

// "smile:1.0,surprise@200:0.8,...": expression[@intensity]:seconds.
std::vector<ScriptStep> parse_script(const std::string& text) {
  std::vector<ScriptStep> steps;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) throw Error("--script item '" + item + "' is not expression:seconds");
    std::string name = item.substr(0, colon);
    int intensity = 255;
    if (const auto at = name.find('@'); at != std::string::npos) intensity = std::stoi(name.substr(at + 1)), name = name.substr(0, at);
    const auto e = expression_from_name(name);
    const double seconds = std::stod(item.substr(colon + 1));
    if (!e || intensity < 0 || intensity > 255 || !(seconds > 0 && seconds < 600)) throw Error("--script item '" + item + "' is not valid");
    steps.push_back({{*e, uint8_t(intensity)}, seconds});
  }
  if (steps.empty()) throw Error("--script is empty");
  return steps;
}

// A frame source: a real one, or a speaker synthesised from one photo following a script.
class Speaker {
 public:
  Speaker(const Options& o) {
    if (!o.speaker.empty()) {
      script_ = parse_script(o.script);
      fps_ = o.fps > 0 ? o.fps : 25;
      FramedFace framed = frame_on_face(load_image(o.speaker), o.face);
      photo_ = std::move(framed.photo);
      actor_.emplace(photo_, framed.landmarks);
    } else {
      source_.emplace(o.input);
      fps_ = o.fps > 0 ? o.fps : source_->fps();
    }
    repeat_ = std::max(o.repeat, 1);
  }
  double fps() const { return fps_; }
  std::optional<Image> next() {
    if (actor_) {
      const double t = double(frame_++) / fps_;
      double end = 0;
      for (const ScriptStep& step : script_) {
        if (t < (end += step.seconds)) {
          if (actor_->expression() != step.state || frame_ == 1) actor_->set_expression(step.state, t);
          actor_->render(t);
          return actor_->read();
        }
      }
      return std::nullopt;
    }
    if (held_ && held_count_ < repeat_) return ++held_count_, held_;
    held_ = source_->next();
    held_count_ = 1;
    return held_;
  }

 private:
  std::optional<VideoSource> source_;
  Image photo_;
  std::vector<ScriptStep> script_;
  std::optional<FaceReconstructor> actor_;
  std::optional<Image> held_;
  int repeat_ = 1, held_count_ = 0, frame_ = 0;
  double fps_ = 25;
};

Image fit_height(const Image& image, int height) {
  return resized(image, std::max(2, int(std::lround(double(image.width) * height / image.height)) & ~1), height);
}

int run(const Options& o) {
  // Everything draws into its own off-screen targets: the context's own surface is never shown.
  auto context = create_offscreen_context(64, 64);
  Speaker speaker(o);
  std::optional<Image> first = speaker.next();
  if (!first) throw Error("the input has no frames");

  // Speaker side: calibration and the neutral photo (sent once, as an asset would be).
  FaceCoder coder({.detect_every = 5, .detect_width = 320, .upsample = first->width < 480 ? 1 : 0});
  const Image neutral = o.neutral.empty() ? *first : load_image(o.neutral);
  const FaceLandmarks neutral_landmarks = coder.calibrate(neutral);

  // Receiver side.
  FaceReconstructor receiver(neutral, neutral_landmarks);
  Canvas paint_canvas(neutral.width, neutral.height, 1);
  std::unique_ptr<VideoPainter> painter;
  if (o.paint != "none") {
    painter = make_video_painter({"style=" + o.paint, "seed=7"}, neutral.width, neutral.height);
    paint_canvas.bind();
    Backdrop(BackdropSpec::parse("canvas")).draw();
  }

  protocol::FrameDecoder wire;
  const int max_frames = o.frames > 0 ? o.frames : 100000, fps = int(std::lround(speaker.fps()));
  FrameWriter writer(o.out, max_frames, fps, false);
  std::optional<FrameWriter> input_writer;
  if (!o.input_out.empty()) input_writer.emplace(o.input_out, max_frames, fps, false);
  int frames = 0, faces = 0;
  std::map<std::string, int> shown;
  const std::vector<std::string> captions = {"speaker", "receiver (codes only)", "painted (" + o.paint + ")"};
  double analysis_ms = 0;
  for (std::optional<Image> frame = std::move(first); frame && (o.frames == 0 || frames < o.frames); frame = speaker.next(), ++frames) {
    const double now = double(frames) / speaker.fps();
    const auto start = std::chrono::steady_clock::now();
    const FaceCoder::Sent sent = coder.read(*frame, now);
    analysis_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    faces += coder.last_face().has_value();
    if (sent.layers) {
      const protocol::Bytes bytes = protocol::encode(*sent.layers);  // over the wire and back
      wire.feed(bytes.data(), bytes.size());
      while (auto received = wire.next())
        if (const auto* face = std::get_if<protocol::MemberLayers>(&*received)) receiver.set_face(protocol::face_state_of(*face), now);
    }
    receiver.render(now);
    const Image reconstruction = receiver.read();  // opaque: the warped photo covers every pixel
    ++shown[name_of(receiver.expression().expression)];
    std::vector<Image> panels = {fit_height(*frame, o.height), fit_height(reconstruction, o.height)};
    if (painter) {
      paint_canvas.bind();
      painter->paint(reconstruction);
      panels.push_back(fit_height(paint_canvas.read(), o.height));
    }
    writer.write(side_by_side(panels, captions));
    if (input_writer) input_writer->write(*frame);
  }
  writer.close();
  if (input_writer) input_writer->close();

  const double seconds = frames / speaker.fps();
  nlohmann::json stats = {{"frames", frames},
                          {"seconds", seconds},
                          {"fps", speaker.fps()},
                          {"faces_found", faces},
                          {"messages", coder.layers_stream().messages()},
                          {"bytes", coder.layers_stream().bytes()},
                          {"bytes_per_second", seconds > 0 ? double(coder.layers_stream().bytes()) / seconds : 0.0},
                          {"single_code_bytes_per_second", seconds > 0 ? double(coder.stream().bytes()) / seconds : 0.0},
                          {"neutral_photo_bytes", neutral.pixels.size()},
                          {"analysis_ms_mean", frames ? analysis_ms / frames : 0.0},
                          {"frames_per_expression", shown}};
  if (!o.json_path.empty()) std::ofstream(o.json_path) << stats.dump(2) << "\n";
  std::cout << stats.dump(2) << "\n";
  // A video of a photo that never moved is not a conference: say so and fail.
  if (faces == 0) throw Error("no face found in any of the " + std::to_string(frames) + " frames (the video shows the neutral photo only)");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"inkwire-conference: speaker (face analysis, expression codes) and receiver (reconstruction) in one process; "
               "writes input | reconstruction | painted reconstruction side by side"};
  Options o;
  app.add_option("--input", o.input, "camera:N, /dev/videoN, a video file, a folder of images or a %04d pattern");
  app.add_option("--speaker", o.speaker, "instead of --input: a speaker made from this photo (the face found in it, framed), following --script");
  app.add_option("--face", o.face, "with --speaker: which face of a group photo speaks, 1 = the leftmost (default: the largest)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--script", o.script, "with --speaker: expression[@intensity]:seconds,... e.g. neutral:1,smile:1,surprise@200:1");
  app.add_option("--neutral", o.neutral, "the speaker's neutral photo (default: the first frame)");
  app.add_option("--out", o.out, "side-by-side video (.mp4) or %04d.png frames")->required();
  app.add_option("--input-out", o.input_out, "also write the speaker's frames as they are (.mp4 or %04d.png), e.g. to feed a server");
  app.add_option("--json", o.json_path, "write the figures (bytes sent, frames, expressions shown) here");
  app.add_option("--paint", o.paint, "painterly style of the third panel, or none")->default_val("impressionist");
  app.add_option("--fps", o.fps, "frame rate (default: the source's)")->check(CLI::Range(1, 120));
  app.add_option("--repeat", o.repeat, "show each input frame this many times (stills as a clip)")->check(CLI::Range(1, 1000));
  app.add_option("--frames", o.frames, "stop after this many frames (0: the whole input)")->check(CLI::Range(0, 100000));
  app.add_option("--height", o.height, "panel height in the output")->check(CLI::Range(64, 2160));
  try {
    app.parse(argc, argv);
    if (o.input.empty() == o.speaker.empty()) throw CLI::ValidationError("give exactly one of --input and --speaker");
    if (!o.speaker.empty() && o.script.empty()) throw CLI::ValidationError("--speaker needs --script");
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "inkwire-conference: " << e.what() << "\n";
    return 1;
  }
}
