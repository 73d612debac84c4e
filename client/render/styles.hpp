#pragma once
// Every registered style: its name, a one-line summary, its parameters with defaults, and how
// to make its renderer. `inkwire-render --style list` prints this table.
#include <functional>
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

// The backdrop a style (or the first style of a combination) is drawn over by default.
std::string default_backdrop(const std::string& name);

}  // namespace inkwire
