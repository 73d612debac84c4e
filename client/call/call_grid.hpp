#pragma once
// A call as its members see it (SPEC F11): a grid of tiles, one per member with a neutral
// photo (and the session's own speaker, when a server-side face source feeds it), each face
// drawn from the codes alone (ConferenceView: the photo deformed to the expression, painted in
// a painterly session), the active speakers framed in colour. Names and states are laid over
// the tiles by whoever shows the grid (tiles() says where), as text is theirs to draw.
#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "client/render/face/conference_view.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class CallGrid {
 public:
  struct Tile {
    uint16_t member = 0;  // 0: the session's own speaker
    std::string name;
    bool speaking = false, camera = false, microphone = false, face_found = true, you = false, has_face = false;
    glm::ivec4 rect{0};  // x, y from the top-left, width, height, in viewport pixels
  };

  // The roster and the cached photo and landmarks files of its members (by member number);
  // members whose files are not there yet get a tile without a face.
  void update(const protocol::Roster& roster, const std::map<uint16_t, std::vector<std::filesystem::path>>& files);
  void set_style(const std::string& renderer, const std::vector<std::string>& settings);
  // A member's face: its layers and pose (SPEC F20-F22).
  void set_face(const protocol::MemberLayers& face);
  // Into the bound framebuffer; `speaker`: the session's own speaker as a tile of its own.
  void draw(glm::ivec2 viewport, double time_seconds, ConferenceView* speaker);
  const std::vector<Tile>& tiles() const { return tiles_; }
  // The expression a member's tile shows (the one code that says most of it), and its whole face.
  std::optional<ExpressionState> expression(uint16_t member) const;
  std::optional<FaceState> face(uint16_t member) const;
  // Whether a tile changes by itself, frame after frame (a painterly face): a grid that does not
  // need drawing again until something changes (the native window and the browser wait so).
  bool animates() const {
    return std::any_of(views_.begin(), views_.end(), [](const auto& v) { return v.second->animates(); });
  }
  // Whether there is a call to show: some member publishes or has a photo. A conference whose
  // members only watch the session's own speaker shows that speaker alone, as before calls.
  bool empty() const {
    return std::none_of(roster_.members.begin(), roster_.members.end(),
                        [](const protocol::CallMember& m) { return m.camera || m.microphone || !m.assets.empty(); });
  }

 private:
  protocol::Roster roster_;
  std::map<uint16_t, std::unique_ptr<ConferenceView>> views_;
  std::map<uint16_t, std::vector<std::filesystem::path>> files_;
  std::string renderer_ = "default";
  std::vector<std::string> settings_;
  std::vector<Tile> tiles_;
};

// The words under a tile, as a person would say them: the name, "(you)", and "listening" (neither
// camera nor microphone), "muted", "camera off" or "no face found"; natively and in the browser.
std::string caption_of(const CallGrid::Tile& tile);

}  // namespace inkwire
