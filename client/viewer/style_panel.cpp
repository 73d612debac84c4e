#include "client/viewer/style_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "client/render/styles.hpp"
#include "common/error.hpp"

namespace inkwire {
namespace {

// Styles drawn as lines only, which a panel offers to lay over another style ("hatching" with
// "sketch-pencil" is "hatching+sketch-pencil").
const std::vector<std::string> kOverlays = {"sketch-pencil", "sketch-charcoal", "sketch-recursive", "sketch-segments", "hidden-line"};

std::pair<std::string, std::string> split_overlay(const std::string& style) {
  const size_t plus = style.find('+');
  if (plus == std::string::npos) return {style, ""};
  return {style.substr(0, plus), style.substr(plus + 1)};
}

bool combo(const char* label, std::string& value, const std::vector<std::string>& choices) {
  bool changed = false;
  if (ImGui::BeginCombo(label, value.c_str())) {
    for (const std::string& c : choices)
      if (ImGui::Selectable(c.c_str(), c == value)) value = c, changed = true;
    ImGui::EndCombo();
  }
  return changed;
}

// A path or free text, applied when the user presses Enter. `edit` holds what is typed while
// the field is active and follows the session's value otherwise.
bool text_field(const char* label, std::string& value, std::string& edit) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "%s", edit.c_str());
  const bool entered = ImGui::InputText(label, buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  const bool changed = entered && value != buffer;
  if (changed) value = buffer;
  edit = ImGui::IsItemActive() ? std::string(buffer) : value;
  return changed;
}

}  // namespace

bool StylePanel::parameter(const ParamSpec& p, std::string& v) {
  const char* label = "##value";  // the name is drawn above
  switch (p.type) {
    case ParamType::Float: {
      float f = std::strtof(v.c_str(), nullptr);
      const ImGuiSliderFlags flags = p.max - p.min > 1000 ? ImGuiSliderFlags_Logarithmic : 0;
      if (ImGui::SliderFloat(label, &f, float(p.min), float(p.max), "%.3g", flags)) return v = param_number(f), true;
      return false;
    }
    case ParamType::Int: {
      int i = std::atoi(v.c_str());
      const int max = int(std::min(p.max, 1e9));
      const ImGuiSliderFlags flags = max - p.min > 1000 ? ImGuiSliderFlags_Logarithmic : 0;
      if (ImGui::SliderInt(label, &i, int(p.min), max, "%d", flags)) return v = std::to_string(i), true;
      return false;
    }
    case ParamType::Bool: {
      bool b = v == "true" || v == "1" || v == "on";
      if (ImGui::Checkbox(label, &b)) return v = b ? "true" : "false", true;
      return false;
    }
    case ParamType::Colour: {
      glm::vec3 c{0.0f};
      try {
        c = parse_hex_colour(v);
      } catch (const Error&) {
      }
      float rgb[3] = {c.r, c.g, c.b};
      if (!ImGui::ColorEdit3(label, rgb)) return false;
      char hex[8];
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", int(std::lround(rgb[0] * 255)), int(std::lround(rgb[1] * 255)), int(std::lround(rgb[2] * 255)));
      return v = hex, true;
    }
    case ParamType::Choice: return combo(label, v, p.choices);
    case ParamType::Text: {
      // One of the usual values, or (where the parameter takes one) a file typed in.
      if (!p.choices.empty()) {
        std::vector<std::string> choices = p.choices;
        if (std::find(choices.begin(), choices.end(), v) == choices.end()) choices.push_back(v);
        if (combo(label, v, choices)) return true;
        if (!p.names_file) return false;
        label = "##file";
      }
      return text_field(label, v, path_edits_.try_emplace(p.name, v).first->second);
    }
  }
  return false;
}

std::optional<protocol::StyleChange> StylePanel::draw(const protocol::StyleChange& current) {
  std::optional<protocol::StyleChange> change;
  auto [base, overlay] = split_overlay(current.renderer);
  const std::vector<std::string> names = style_names();
  ImGui::PushItemWidth(-1);
  ImGui::TextUnformatted("style");
  bool restyled = combo("##style", base, names);
  std::vector<std::string> overlays = {"none"};
  for (const std::string& o : kOverlays)
    if (o != base) overlays.push_back(o);
  std::string over = overlay.empty() ? "none" : overlay;
  ImGui::TextUnformatted("lines over it");
  restyled |= combo("##overlay", over, overlays);
  ImGui::PopItemWidth();
  if (restyled) {
    pending_.clear();
    return protocol::StyleChange{.renderer = over == "none" ? base : base + "+" + over, .settings = {}};
  }

  if (current.renderer != specs_style_) {  // none for a style this client does not know
    specs_style_ = current.renderer;
    pending_.clear();
    try {
      specs_ = style_param_specs(current.renderer);
    } catch (const Error&) {
      specs_.clear();
    }
  }
  std::string key = current.renderer;
  for (const std::string& s : current.settings) key += ";" + s;
  if (key != in_effect_key_) {
    in_effect_key_ = key;
    in_effect_error_.clear();
    try {
      in_effect_ = style_settings_in_effect(current.renderer, current.settings);
    } catch (const Error& e) {
      in_effect_.clear();
      in_effect_error_ = e.what();
    }
    // Echoed by the session: no longer pending.
    std::erase_if(pending_, [&](const auto& kv) {
      return std::find(current.settings.begin(), current.settings.end(), kv.first + "=" + kv.second) != current.settings.end();
    });
  }
  if (specs_.empty() || !ImGui::CollapsingHeader("parameters", ImGuiTreeNodeFlags_DefaultOpen)) return change;
  for (const ParamSpec& p : specs_) {
    // The name above its widget: a narrow docked panel has no room beside it.
    ImGui::TextUnformatted(p.name.c_str());
    std::string value = pending_.count(p.name) ? pending_[p.name] : in_effect_.count(p.name) ? in_effect_[p.name] : p.default_value;
    ImGui::PushID(p.name.c_str());
    ImGui::PushItemWidth(-1);
    const bool edited = parameter(p, value);
    ImGui::PopItemWidth();
    if (edited) pending_[p.name] = value;
    // A dragged slider goes to the session once, when let go (every client redraws, a painting
    // scatters its brushes, on each change); lists, boxes and fields at once.
    const bool let_go = ImGui::IsItemDeactivatedAfterEdit() && pending_.count(p.name);
    if ((edited && !ImGui::IsItemActive()) || let_go) {
      // The session's own settings with this one replaced: values the user never touched stay
      // unset, so a placeholder ("0 takes the style file's") keeps following its style file.
      protocol::StyleChange next{.renderer = current.renderer, .settings = {}};
      for (const std::string& s : current.settings)
        if (s.substr(0, s.find('=')) != p.name) next.settings.push_back(s);
      next.settings.push_back(p.name + "=" + pending_[p.name]);
      change = std::move(next);
    }
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%s", p.help.c_str());
    ImGui::PopID();
  }
  if (!in_effect_error_.empty()) ImGui::TextWrapped("%s", in_effect_error_.c_str());
  return change;
}

}  // namespace inkwire
