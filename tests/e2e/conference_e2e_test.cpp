// A conference end to end on 127.0.0.1 (SPEC F1-F5 over N1-N5): a real inkwire-server analyses
// a speaker's video and sends expression codes; real headless inkwire-client processes deform
// the neutral photo, fetched once, by those codes alone.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "client/gl/canvas.hpp"
#include "client/gl/context.hpp"
#include "client/net/session_client.hpp"
#include "client/viewer/session_view.hpp"
#include "e2e_support.hpp"

using namespace inkwire;
using namespace inkwire::e2e;

namespace {

// Packaged with libdlib-dev and libdlib-data (scripts/packages.txt).
const fs::path kSpeakerPhoto = "/usr/share/doc/libdlib19.1/examples/faces/Tom_Cruise_avp_2014_4.jpg";
constexpr int kFps = 15;
constexpr glm::ivec2 kClientSize{240, 180};

// The conference state with `expression` drawn here once its tween has ended.
Image render_locally(protocol::Snapshot state, const std::vector<fs::path>& files, const protocol::ExpressionCode& expression) {
  auto context = create_offscreen_context(kClientSize.x, kClientSize.y);
  Canvas canvas(kClientSize.x, kClientSize.y, 4);
  state.expression = expression;
  SessionView view;
  view.update(state, files);
  canvas.bind();
  view.draw(kClientSize, 0.0, 0);
  view.draw(kClientSize, 1.0, 1);
  return canvas.read();
}

protocol::ExpressionCode code_of(const nlohmann::json& logged) {
  const auto expression = expression_from_name(logged.at("name").get<std::string>());
  return {.code = uint8_t(expression.value()), .intensity = logged.at("intensity").get<uint8_t>(), .sequence = 0};
}

// Frames whose expression had been shown for the three frames before (its tween has ended).
std::vector<size_t> settled_frames(const std::vector<nlohmann::json>& log) {
  std::vector<size_t> settled;
  for (size_t i = 3; i < log.size(); ++i)
    if (log[i]["expression"] == log[i - 1]["expression"] && log[i]["expression"] == log[i - 3]["expression"]) settled.push_back(i);
  return settled;
}

glm::dvec3 mean_colour(const Image& image) {
  glm::dvec3 sum(0);
  for (size_t i = 0; i < image.pixels.size(); i += 4) sum += glm::dvec3(image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]);
  return sum / double(image.pixels.size() / 4);
}

}  // namespace

TEST(ConferenceE2ETest, ClientsShowTheSpeakersExpressionsFromCodesAloneAndPaintThemOnRequest) {
  if (!fs::exists(kSpeakerPhoto) || !fs::exists(kFaceModel)) GTEST_SKIP() << "libdlib-dev's example faces or libdlib-data's model is missing";
  const fs::path dir = output_dir("conference");

  // The speaker: a clip synthesised from one packaged photo, played by the server as a camera.
  Process synthesis("inkwire-conference",
                    {"--speaker", kSpeakerPhoto.string(), "--script", "neutral:1.2,surprise:1.2,smile@200:1.2", "--fps", std::to_string(kFps),
                     "--paint", "none", "--height", "64", "--out", (dir / "side.mp4").string(), "--input-out",
                     (dir / "speaker.mp4").string()},
                    dir / "synthesis.log");
  ASSERT_EQ(synthesis.wait(), 0) << synthesis.output();
  const nlohmann::json config = {
      {"sessions",
       {{{"name", "meeting"}, {"kind", "conference"},
         {"face", {{"source", (dir / "speaker.mp4").string()}, {"neutral", kSpeakerPhoto.string()}, {"fps", kFps}}}}}}};
  ServerUnderTest server(dir, config);
  ASSERT_EQ(log_events(server.process().output(), "face-source-started").size(), 1u) << server.process().output();

  // A viewer for five seconds: more than one pass of the 3.6 s clip.
  auto viewer = headless_client(server, "meeting", dir, "viewer", 5 * kFps, kFps);
  ASSERT_EQ(viewer->wait(), 0) << viewer->output();
  const auto log = frame_log(dir / "viewer.jsonl");
  ASSERT_EQ(log.size(), size_t(5 * kFps));

  SessionClient a(server.address(), "a");
  const protocol::Snapshot state = a.join("meeting", "");
  AssetCache cache(dir / "cache-a");
  const auto files = a.fetch_assets(state, cache);
  ASSERT_EQ(files.size(), 2u) << "the neutral photo and its landmarks";

  // Every expression of the clip reached the viewer, and each settled frame is exactly the photo
  // deformed by the code it logged.
  std::map<std::string, Image> shown;
  for (const size_t i : settled_frames(log)) {
    const std::string name = log[i]["expression"]["name"];
    if (shown.count(name)) continue;
    SCOPED_TRACE("frame " + std::to_string(i) + ": " + log[i].dump());
    shown[name] = load_image(client_frame(dir, "viewer", int(i)));
    EXPECT_LT(mean_difference(shown[name], render_locally(state, files, code_of(log[i]["expression"]))), 1.0);
  }
  // Which code the server picks for the synthesised smile depends on its analysis (a broad
  // smile may read as laugh); the neutral and surprised phases are unambiguous.
  for (const char* expected : {"neutral", "surprise"}) EXPECT_TRUE(shown.count(expected)) << "never showed " << expected;
  EXPECT_GE(shown.size(), 3u) << "the smiling phase showed no third expression";
  if (shown.count("neutral") && shown.count("surprise")) {
    EXPECT_GT(mean_difference(shown["neutral"], shown["surprise"]), 0.5) << "surprise does not move the face";
  }

  // One member asks for paint: every member's face is painted from then on, over the last frame.
  a.send(protocol::StyleChange{.renderer = "painterly", .settings = {"style=impressionist"}});
  auto painted = headless_client(server, "meeting", dir, "painted", 12, 6);
  ASSERT_EQ(painted->wait(), 0) << painted->output();
  const auto painted_log = frame_log(dir / "painted.jsonl");
  ASSERT_EQ(painted_log.size(), 12u);
  EXPECT_EQ(painted_log.back()["style"], "painterly style=impressionist");
  const Image last = load_image(client_frame(dir, "painted", 11));
  const Image plain = render_locally(state, files, code_of(painted_log.back()["expression"]));
  EXPECT_GT(mean_difference(last, plain), 3.0) << "the painted face looks like the photo itself";
  EXPECT_LT(glm::length(mean_colour(last) - mean_colour(plain)), 30.0) << "the painting lost the photo's colours";

  // Only codes crossed the wire while the speaker spoke: under 1 kbit/s.
  server.process().kill(SIGTERM);
  ASSERT_EQ(server.process().wait(), 0);
  const auto ended = log_events(server.process().output(), "face-source-ended");
  ASSERT_EQ(ended.size(), 1u) << server.process().output();
  const double seconds = ended[0]["frames"].get<double>() / kFps;
  ASSERT_GT(seconds, 5.0);
  EXPECT_LT(ended[0]["bytes"].get<double>() * 8 / seconds, 1000.0) << ended[0].dump();
}

// A group photo as the speaker: the faces are found at the photo's own scale, the largest (or the
// one asked for) speaks, framed; a scripted smile comes out as a smile, not a laugh; a photo
// without a face is refused with the program's name and a reason.
TEST(ConferenceE2ETest, AGroupPhotoSpeaksThroughItsLargestFaceAndASmileStaysASmile) {
  const fs::path group = fs::path(kSpeakerPhoto).parent_path() / "bald_guys.jpg", dogs = fs::path(kSpeakerPhoto).parent_path() / "dogs.jpg";
  if (!fs::exists(group) || !fs::exists(kFaceModel)) GTEST_SKIP() << "libdlib-dev's example faces or libdlib-data's model is missing";
  const fs::path dir = output_dir("conference-group");
  for (const std::string face : {"", "2"}) {
    std::vector<std::string> args = {"--speaker", group.string(), "--script", "neutral:0.4,smile:1.2", "--paint", "none",
                                     "--out", (dir / ("group" + face + ".mp4")).string(), "--json", (dir / ("group" + face + ".json")).string()};
    if (!face.empty()) args.insert(args.end(), {"--face", face});
    Process conference("inkwire-conference", args, dir / ("group" + face + ".log"));
    ASSERT_EQ(conference.wait(std::chrono::seconds(120)), 0) << conference.output();
    const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / ("group" + face + ".json")));
    EXPECT_EQ(stats["faces_found"], stats["frames"]) << "the framed face is followed in every frame";
    if (!face.empty()) continue;  // another face of the group speaks too; its expressions are judged below for the largest
    const auto& shown = stats["frames_per_expression"];
    EXPECT_GT(shown.value("smile", 0), 10) << shown.dump();
    EXPECT_EQ(shown.value("laugh", 0), 0) << "a scripted smile came out as a laugh: " << shown.dump();
  }
  Process no_face("inkwire-conference", {"--speaker", dogs.string(), "--script", "smile:1", "--out", (dir / "dogs.mp4").string()}, dir / "dogs.log");
  EXPECT_NE(no_face.wait(std::chrono::seconds(60)), 0);
  EXPECT_NE(no_face.output().find("inkwire-conference: --speaker photo shows no face"), std::string::npos) << no_face.output();

  // A camera that never sees a face: frames were written, but no conference took place.
  fs::create_directories(dir / "empty-room");
  for (int i = 0; i < 3; ++i) save_image(Image(160, 120, {70, 120, 60, 255}), dir / "empty-room" / ("frame" + std::to_string(i) + ".png"));
  Process empty_room("inkwire-conference", {"--input", (dir / "empty-room").string(), "--neutral", kSpeakerPhoto.string(), "--paint", "none",
                                            "--out", (dir / "empty-room.mp4").string()}, dir / "empty-room.log");
  EXPECT_NE(empty_room.wait(std::chrono::seconds(60)), 0);
  EXPECT_NE(empty_room.output().find("inkwire-conference: no face found in any of the 3 frames"), std::string::npos) << empty_room.output();
}

// A wink scripted on a speaker photo is seen by the analysis (the shut eye's shade, where the
// landmarks do not follow the lid) and shown by the receiver on the same eye.
TEST(ConferenceE2ETest, AScriptedWinkIsSeenOnTheSameEye) {
  const fs::path group = fs::path(kSpeakerPhoto).parent_path() / "bald_guys.jpg";
  if (!fs::exists(group) || !fs::exists(kFaceModel)) GTEST_SKIP() << "libdlib-dev's example faces or libdlib-data's model is missing";
  const fs::path dir = output_dir("conference-wink");
  Process conference("inkwire-conference", {"--speaker", group.string(), "--script", "neutral:0.4,wink-left:1.2", "--paint", "none",
                                            "--out", (dir / "wink.mp4").string(), "--json", (dir / "wink.json").string()},
                     dir / "wink.log");
  ASSERT_EQ(conference.wait(std::chrono::seconds(120)), 0) << conference.output();
  const auto shown = nlohmann::json::parse(std::ifstream(dir / "wink.json"))["frames_per_expression"];
  EXPECT_GT(shown.value("wink-left", 0), 10) << shown.dump();
  EXPECT_EQ(shown.value("wink-right", 0), 0) << shown.dump();
}

// A blink of 150 ms on a speaker photo, at a camera's 15 pictures a second (SPEC F22): the server
// reads it (both eyes' lids falling together, though dlib's model follows a shut lid part way)
// and the receiver draws the eyes shut for about as long, then open again.
TEST(ConferenceE2ETest, AScriptedBlinkOf150MillisecondsIsDrawnAsABlinkAndTheEyesOpenAgain) {
  if (!fs::exists(kSpeakerPhoto) || !fs::exists(kFaceModel)) GTEST_SKIP() << "libdlib-dev's example faces or libdlib-data's model is missing";
  const fs::path dir = output_dir("conference-blink");
  Process conference("inkwire-conference", {"--speaker", kSpeakerPhoto.string(), "--script", "neutral:1,eyes-closed:0.15,neutral:1", "--fps", "15",
                                            "--paint", "none", "--out", (dir / "blink.mp4").string(), "--json", (dir / "blink.json").string()},
                     dir / "blink.log");
  ASSERT_EQ(conference.wait(std::chrono::seconds(120)), 0) << conference.output();
  const auto shown = nlohmann::json::parse(std::ifstream(dir / "blink.json"))["frames_per_expression"];
  EXPECT_GE(shown.value("eyes-closed", 0), 1) << "no blink drawn: " << shown.dump();
  EXPECT_LE(shown.value("eyes-closed", 0), 5) << "the eyes stayed shut: " << shown.dump();
  EXPECT_GE(shown.value("neutral", 0), 28) << shown.dump();
}
