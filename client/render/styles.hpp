#pragma once
// Every registered style: its name, a one-line summary, its parameters with defaults, and how
// to make its renderer. `inkwire-render --style list` prints this table.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "client/render/renderer.hpp"

namespace inkwire {

struct StyleInfo {
  std::string name;
  std::string summary;
  std::string default_backdrop;  // what --backdrop means when not given
  std::function<std::vector<ParamSpec>()> params;
  std::function<std::unique_ptr<Renderer>()> create;
  // How often the picture changes on its own when nothing else does (boiling lines, drifting
  // brushes); 0: a still object is a still picture, so a window need not redraw it.
  double redraw_hz = 0.0;
  // The values a configuration really uses where a parameter says "0 takes the style file's"
  // (painterly): null when every value is used as given.
  std::function<std::map<std::string, std::string>(const StyleParams&)> in_effect = nullptr;
  // The backdrop a configuration asks for (a painting style file's ground), or "": the default.
  std::function<std::string(const StyleParams&)> ground = nullptr;
};

const std::vector<StyleInfo>& styles();

// Throws inkwire::Error listing the known names when `name` is not one of them.
const StyleInfo& find_style(const std::string& name);

// Makes a renderer for `name`, configured with defaults overridden by `assignments` (KEY=VALUE).
// "a+b" combines styles drawn in turn over one backdrop (e.g. "hatching+sketch-charcoal"); an
// assignment goes to every part that has the key, and one no part has is an error.
std::unique_ptr<Renderer> make_renderer(const std::string& name, const std::vector<std::string>& assignments = {});

// The configuration make_renderer() would give each part, without making a renderer; throws
// what it would throw (unknown style, unknown key, bad value).
std::vector<StyleParams> style_params(const std::string& name, const std::vector<std::string>& assignments = {});

// Every parameter of a style, or of a joined style's parts ('a+b'; a name the parts share is
// one parameter, set in all of them, described by the first). Throws inkwire::Error for an
// unknown style.
std::vector<ParamSpec> style_param_specs(const std::string& name);

// Every parameter's value in effect for `name` (joined styles too) configured by `assignments`:
// defaults, then the assignments, then what placeholders stand for. Throws as style_params().
std::map<std::string, std::string> style_settings_in_effect(const std::string& name, const std::vector<std::string>& assignments);

// The rate at which a style (the fastest of a joined style's parts) changes a still picture.
double style_redraw_hz(const std::string& name);

// The registered style names, for parameters that name another style (a painting's reference).
std::vector<std::string> style_names();

// The backdrop a style (or the first style of a combination) is drawn over by default, as
// configured by `assignments` (a painting style file may name its own ground).
std::string default_backdrop(const std::string& name, const std::vector<std::string>& assignments = {});

}  // namespace inkwire
