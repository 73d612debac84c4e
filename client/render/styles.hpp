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
std::unique_ptr<Renderer> make_renderer(const std::string& name, const std::vector<std::string>& assignments = {});

}  // namespace inkwire
