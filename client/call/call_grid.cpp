#include "client/call/call_grid.hpp"

#include <algorithm>
#include <cmath>

#include "client/gl/gl.hpp"
#include "common/error.hpp"
#include "protocol/face_versions.hpp"

namespace inkwire {
namespace {

constexpr int kGap = 6, kCaption = 22;  // pixels between tiles; under each tile for its name

}  // namespace

std::string caption_of(const CallGrid::Tile& t) {
  std::string text = t.name + (t.you ? " (you)" : "");
  if (t.member == 0) return text;
  if (!t.camera && !t.microphone) return text + ", listening";
  if (!t.microphone) text += ", muted";
  if (!t.camera) text += ", camera off";
  else if (!t.face_found) text += t.you ? ": no face found in your camera picture" : ": no face found";
  return text;
}

void CallGrid::update(const protocol::Roster& roster, const std::map<uint16_t, std::vector<std::filesystem::path>>& files) {
  roster_ = roster;
  for (const auto& member : roster.members) {
    const auto it = files.find(member.member);
    if (it == files.end() || it->second.size() != 2) continue;
    if (files_[member.member] == it->second && views_.count(member.member)) continue;
    files_[member.member] = it->second;
    try {
      auto view = std::make_unique<ConferenceView>(it->second[0], it->second[1]);
      view->set_style(renderer_, settings_);
      views_[member.member] = std::move(view);
    } catch (const Error& e) {
      std::fprintf(stderr, "inkwire-client: cannot show %s: %s\n", member.name.c_str(), e.what());
    }
  }
  // Members who left take their views with them.
  std::erase_if(views_, [&](const auto& v) {
    return std::none_of(roster.members.begin(), roster.members.end(), [&](const auto& m) { return m.member == v.first; });
  });
}

void CallGrid::set_style(const std::string& renderer, const std::vector<std::string>& settings) {
  if (renderer == renderer_ && settings == settings_) return;  // a painted face keeps its strokes
  renderer_ = renderer, settings_ = settings;
  for (auto& [member, view] : views_) view->set_style(renderer, settings);
}

void CallGrid::set_face(const protocol::MemberLayers& face) {
  if (const auto it = views_.find(face.member); it != views_.end()) it->second->set_face(protocol::face_state_of(face));
}

std::optional<ExpressionState> CallGrid::expression(uint16_t member) const {
  const auto it = views_.find(member);
  if (it == views_.end()) return std::nullopt;
  return it->second->expression();
}

std::optional<FaceState> CallGrid::face(uint16_t member) const {
  const auto it = views_.find(member);
  if (it == views_.end()) return std::nullopt;
  return it->second->face();
}

void CallGrid::draw(glm::ivec2 viewport, double time_seconds, ConferenceView* speaker) {
  tiles_.clear();
  if (speaker) tiles_.push_back({.member = 0, .name = "speaker", .has_face = true});
  for (const auto& m : roster_.members)
    // Framed as speaking by the voice alone: only a live microphone speaks.
    tiles_.push_back({.member = m.member, .name = m.name, .speaking = m.speaking && m.microphone, .camera = m.camera, .microphone = m.microphone,
                      .face_found = m.face_found, .you = m.member == roster_.you, .has_face = views_.count(m.member) > 0});
  if (tiles_.empty()) return;
  // A call is a dark room whatever the style's backdrop: the tiles and their captions read on it.
  gl::glClearColor(0.16f, 0.16f, 0.18f, 1);
  gl::glClear(GL_COLOR_BUFFER_BIT);
  const int n = int(tiles_.size());
  // The layout whose tiles come out largest at the faces' 4:3.
  int best_cols = 1;
  float best_side = 0;
  for (int cols = 1; cols <= n; ++cols) {
    const int rows = (n + cols - 1) / cols;
    const float w = float(viewport.x - kGap * (cols + 1)) / float(cols), h = float(viewport.y - (kGap + kCaption) * rows - kGap) / float(rows);
    const float side = std::min(w, h * 4.0f / 3.0f);
    if (side > best_side) best_side = side, best_cols = cols;
  }
  const int cols = best_cols, rows = (n + cols - 1) / cols;
  const int w = std::max(1, (viewport.x - kGap * (cols + 1)) / cols), h = std::max(1, (viewport.y - (kGap + kCaption) * rows - kGap) / rows);
  gl::glEnable(GL_SCISSOR_TEST);
  for (int i = 0; i < n; ++i) {
    Tile& t = tiles_[size_t(i)];
    t.rect = {kGap + (i % cols) * (w + kGap), kGap + (i / cols) * (h + kGap + kCaption), w, h};
    const int gl_y = viewport.y - t.rect.y - h;  // GL counts rows from the bottom
    // An active speaker's tile is framed in colour: a clear a little larger than the tile.
    const int frame = t.speaking ? 4 : 1;
    gl::glScissor(t.rect.x - frame, gl_y - frame, w + 2 * frame, h + 2 * frame);
    if (t.speaking) gl::glClearColor(0.2f, 0.75f, 0.35f, 1);
    else gl::glClearColor(0.35f, 0.35f, 0.38f, 1);
    gl::glClear(GL_COLOR_BUFFER_BIT);
    gl::glScissor(t.rect.x, gl_y, w, h);
    gl::glClearColor(0.12f, 0.12f, 0.14f, 1);
    gl::glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl::glDisable(GL_SCISSOR_TEST);  // the face renders into buffers of its own first
    gl::glViewport(t.rect.x, gl_y, w, h);
    ConferenceView* view = t.member == 0 ? speaker : views_.count(t.member) ? views_.at(t.member).get() : nullptr;
    if (view) view->draw({w, h}, time_seconds);
    gl::glEnable(GL_SCISSOR_TEST);
  }
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glViewport(0, 0, viewport.x, viewport.y);
}

}  // namespace inkwire
