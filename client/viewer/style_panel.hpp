#pragma once
// The window's side panel: the session's style and every parameter of it, each in the form its
// type asks (sliders, combos, a colour picker, a path field), showing the values in effect.
// It draws inside an ImGui window its caller opens; what the user changes comes back as one
// style change for the whole session.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/style_params.hpp"
#include "protocol/messages.hpp"

namespace inkwire {

class StylePanel {
 public:
  // Draws the style choosers and the parameters of `current`; returns the change to send when
  // the user made one this frame.
  std::optional<protocol::StyleChange> draw(const protocol::StyleChange& current);

 private:
  // The widget for one parameter; true when the user changed `value`.
  bool parameter(const ParamSpec& spec, std::string& value);

  std::string specs_style_;  // the style `specs_` describes
  std::vector<ParamSpec> specs_;
  std::string in_effect_key_;  // style and settings `in_effect_` was worked out for
  std::map<std::string, std::string> in_effect_;
  std::string in_effect_error_;
  // What the user set and the session has not echoed yet: shown meanwhile, so a dragged
  // slider does not jump back while its change travels.
  std::map<std::string, std::string> pending_;
  std::map<std::string, std::string> path_edits_;  // text being typed into path fields
};

}  // namespace inkwire
