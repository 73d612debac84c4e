// Faces in the browser drawn by the native C++ (SPEC F16): a call's grid, the native client's
// CallGrid (client/call/call_grid.cpp), and a conference's speaker, its ConferenceView
// (client/render/face/), compiled to WebAssembly. Each face is a neutral photo deformed by the
// expression codes, in the session's style (plain, comic, painterly, any painterly look a session
// names) exactly as natively. JavaScript keeps the session (the worker, the assets) and the
// captions; it hands this module a photo and its landmarks once, the roster as it changes and
// each expression as it is due.
#include <emscripten/bind.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "client/call/call_grid.hpp"
#include "client/gl/gl.hpp"
#include "client/web/module/module_class.hpp"
#include "common/error.hpp"
#include "protocol/face_versions.hpp"

namespace inkwire {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// Where a member's files go in the module's memory file system: CallGrid reads faces from files,
// as the native client reads them from its asset cache.
const fs::path kFaceFolder = "/faces";

// Writes a photo (`size` bytes at `address`) and its landmarks where ConferenceView reads them.
std::vector<fs::path> write_face(const std::string& stem, uintptr_t address, size_t size, const std::string& landmarks_json) {
  fs::create_directories(kFaceFolder);
  const fs::path photo = kFaceFolder / (stem + ".img"), landmarks = kFaceFolder / (stem + ".json");
  std::ofstream(photo, std::ios::binary).write(reinterpret_cast<const char*>(address), std::streamsize(size));
  std::ofstream(landmarks) << landmarks_json;
  return {photo, landmarks};
}

std::string expression_json(const std::optional<ExpressionState>& e) {
  return e ? json{{"code", int(e->expression)}, {"name", name_of(e->expression)}, {"intensity", e->intensity}}.dump() : "null";
}

// The expressions' names by code, as the protocol numbers them.
std::string expression_names_json() {
  json names = json::array();
  for (int code = 0; code < kExpressionCount; ++code) names.push_back(name_of(Expression(code)));
  return names.dump();
}

}  // namespace

class CallGridView {
 public:
  explicit CallGridView(const std::string& canvas_selector) : canvas_(canvas_selector) {}
  std::string error() const { return canvas_.error(); }

  // A member's neutral photo (JPEG or PNG, `size` bytes at `address`) and its landmarks (the
  // server's JSON): the member's tile shows a face from the next set_roster() on.
  std::string set_member_face(int member, uintptr_t address, size_t size, const std::string& landmarks_json) {
    return guarded([&] {
      // A new name for every photo: CallGrid makes a member's view again when its files change.
      for (const fs::path& old : files_[uint16_t(member)]) fs::remove(old);
      files_[uint16_t(member)] = write_face("member-" + std::to_string(member) + "-" + std::to_string(++versions_[member]), address, size, landmarks_json);
    });
  }

  // The roster: {"you": N, "members": [{"member", "name", "camera", "microphone", "speaking",
  // "face_found"}]} (the protocol's roster as the page decoded it).
  std::string set_roster(const std::string& roster_json) {
    return guarded([&] {
      const json j = json::parse(roster_json);
      protocol::Roster roster;
      roster.you = j.value("you", uint16_t(0));
      for (const json& m : j.at("members"))
        roster.members.push_back({.member = m.at("member").get<uint16_t>(), .name = m.value("name", ""), .camera = m.value("camera", false),
                                  .microphone = m.value("microphone", false), .speaking = m.value("speaking", false),
                                  .face_found = m.value("face_found", true)});
      std::erase_if(files_, [&](const auto& f) {
        return std::none_of(roster.members.begin(), roster.members.end(), [&](const auto& m) { return m.member == f.first; });
      });
      grid_.update(roster, files_);
    });
  }

  // The session's style and its settings (a JSON list of "KEY=VALUE").
  std::string set_style(const std::string& renderer, const std::string& settings_json) {
    return guarded([&] { grid_.set_style(renderer, settings_of(settings_json)); });
  }

  // A member's expression as a member-face says it (a server or recording of protocol version
  // 7), from the next drawn frame on; a code this version does not know shows as neutral.
  void set_face(int member, int code, int intensity, int yaw, int pitch, int roll) {
    const auto byte = [](int v) { return int8_t(std::clamp(v, -128, 127)); };
    grid_.set_face(protocol::member_layers_of({.member = uint16_t(member),
                                               .expression = {.code = uint8_t(std::clamp(code, 0, 255)), .intensity = uint8_t(std::clamp(intensity, 0, 255))},
                                               .yaw = byte(yaw), .pitch = byte(pitch), .roll = byte(roll)}));
  }

  // A member's face from the next drawn frame on, as a member-layers message says it (SPEC
  // F20-F22): the expression's and the mouth's codes and intensities, each eye's openness in
  // percent, the head's yaw, pitch and roll in degrees. Out of range (the page's codec refuses
  // such messages) is ignored.
  void set_layers(int member, int expression, int expression_intensity, int mouth, int mouth_intensity, int eye_left, int eye_right, int yaw,
                  int pitch, int roll) {
    const auto e = expression_from_code(uint8_t(std::clamp(expression, 0, 255))), m = expression_from_code(uint8_t(std::clamp(mouth, 0, 255)));
    const auto in = [](int v, int lo, int hi) { return v >= lo && v <= hi; };
    if (!e || !m || !expression_layer_takes(*e) || !mouth_layer_takes(*m) || !in(expression_intensity, 0, 255) || !in(mouth_intensity, 0, 255) ||
        !in(eye_left, 0, kMaxEyeOpenness) || !in(eye_right, 0, kMaxEyeOpenness))
      return;
    for (int angle : {yaw, pitch, roll})
      if (!in(angle, -protocol::kMaxPoseDegrees, protocol::kMaxPoseDegrees)) return;
    grid_.set_face({.member = uint16_t(member), .yaw = int8_t(yaw), .pitch = int8_t(pitch), .roll = int8_t(roll),
                    .expression = {*e, uint8_t(expression_intensity)}, .mouth = {*m, uint8_t(mouth_intensity)},
                    .eye_left = uint8_t(eye_left), .eye_right = uint8_t(eye_right)});
  }

  // One frame of the grid at `time_seconds` into the canvas's drawing buffer.
  std::string draw(double time_seconds) {
    return guarded([&] {
      const glm::ivec2 size = canvas_.begin_frame();
      grid_.draw(size, time_seconds, nullptr);
    });
  }

  // Where the last frame put each tile (drawing-buffer pixels from the top left), what it shows
  // and its caption: the page writes the captions under the tiles.
  std::string tiles_json() const {
    json tiles = json::array();
    for (const CallGrid::Tile& t : grid_.tiles())
      tiles.push_back({{"member", t.member}, {"name", t.name}, {"caption", caption_of(t)}, {"speaking", t.speaking}, {"camera", t.camera}, {"microphone", t.microphone},
                       {"face_found", t.face_found}, {"you", t.you}, {"has_face", t.has_face}, {"rect", {t.rect.x, t.rect.y, t.rect.z, t.rect.w}}});
    return tiles.dump();
  }

  bool animates() const { return grid_.animates(); }

  // The expression a member's tile shows: {"code", "name", "intensity"}, or null.
  std::string member_expression_json(int member) const { return expression_json(grid_.expression(uint16_t(member))); }
  // The face a member's tile is drawn to: {"pose": [yaw, pitch, roll], "eyes": [left, right],
  // "layers": [expression, mouth]}, or null.
  std::string member_face_json(int member) const {
    const auto face = grid_.face(uint16_t(member));
    if (!face) return "null";
    return json{{"pose", {face->pose.yaw, face->pose.pitch, face->pose.roll}},
                {"eyes", {face->layers.eye_left, face->layers.eye_right}},
                {"layers", {name_of(face->layers.expression.expression), name_of(face->layers.mouth.expression)}}}
        .dump();
  }

 private:
  ModuleCanvas canvas_;
  CallGrid grid_;
  std::map<uint16_t, std::vector<fs::path>> files_;
  std::map<int, int> versions_;
};

// A conference's speaker (<inkwire-conference>): one face filling the canvas, as the native
// client's SessionView shows a conference session.
class FaceView {
 public:
  explicit FaceView(const std::string& canvas_selector) : canvas_(canvas_selector) {}
  std::string error() const { return canvas_.error(); }

  // The speaker's neutral photo (`size` bytes at `address`) and its landmarks' JSON.
  std::string set_face(uintptr_t address, size_t size, const std::string& landmarks_json) {
    return guarded([&] {
      const std::vector<fs::path> files = write_face("speaker-" + std::to_string(++version_), address, size, landmarks_json);
      view_.emplace(files[0], files[1]);
      view_->set_style(renderer_, settings_);
      for (const fs::path& f : files) fs::remove(f);
    });
  }

  std::string set_style(const std::string& renderer, const std::string& settings_json) {
    return guarded([&] {
      std::vector<std::string> settings = settings_of(settings_json);
      if (view_ && (renderer != renderer_ || settings != settings_)) view_->set_style(renderer, settings);
      renderer_ = renderer, settings_ = std::move(settings);
    });
  }

  // The expression from the next drawn frame on; a code this version does not know is ignored.
  void set_expression(int code, int intensity) {
    if (code < 0 || code > 255 || !view_) return;
    if (const auto e = expression_from_code(uint8_t(code))) view_->set_expression({.expression = *e, .intensity = uint8_t(std::clamp(intensity, 0, 255))});
  }

  std::string draw(double time_seconds) {
    return guarded([&] {
      const glm::ivec2 size = canvas_.begin_frame();
      gl::glClearColor(1, 1, 1, 1);
      gl::glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      if (view_) view_->draw(size, time_seconds);
    });
  }

  // Whether the picture changes by itself (a painterly face's brushes move).
  bool animates() const { return view_ && view_->animates(); }
  int painted_frames() const { return view_ ? view_->painted_frames() : 0; }
  std::string expression() const { return expression_json(view_ ? std::optional(view_->expression()) : std::nullopt); }

 private:
  ModuleCanvas canvas_;
  std::optional<ConferenceView> view_;
  std::string renderer_ = "default";
  std::vector<std::string> settings_;
  int version_ = 0;
};

}  // namespace inkwire

EMSCRIPTEN_BINDINGS(inkwire_faces) {
  using namespace emscripten;
  using inkwire::CallGridView;
  class_<CallGridView>("CallGridView")
      .constructor<std::string>()
      .function("error", &CallGridView::error)
      .function("setMemberFace", &CallGridView::set_member_face)
      .function("setRoster", &CallGridView::set_roster)
      .function("setStyle", &CallGridView::set_style)
      .function("setFace", &CallGridView::set_face)
      .function("setLayers", &CallGridView::set_layers)
      .function("draw", &CallGridView::draw)
      .function("tilesJson", &CallGridView::tiles_json)
      .function("animates", &CallGridView::animates)
      .function("expressionJson", &CallGridView::member_expression_json)
      .function("faceJson", &CallGridView::member_face_json);
  using inkwire::FaceView;
  class_<FaceView>("FaceView")
      .constructor<std::string>()
      .function("error", &FaceView::error)
      .function("setFace", &FaceView::set_face)
      .function("setStyle", &FaceView::set_style)
      .function("setExpression", &FaceView::set_expression)
      .function("draw", &FaceView::draw)
      .function("animates", &FaceView::animates)
      .function("paintedFrames", &FaceView::painted_frames)
      .function("expressionJson", &FaceView::expression);
  function("expressionNamesJson", &inkwire::expression_names_json);
}
