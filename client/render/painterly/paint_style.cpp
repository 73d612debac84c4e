#include "client/render/painterly/paint_style.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "client/render/backdrop.hpp"
#include "common/error.hpp"
#include "common/style_params.hpp"

namespace inkwire {

const std::map<std::string, std::string_view>& painterly_style_files();  // generated from styles/

namespace {

using nlohmann::json;

// Reads one style file; every error names the file and the key it is about.
class StyleReader {
 public:
  StyleReader(std::string source, std::filesystem::path folder) : source_(std::move(source)), folder_(std::move(folder)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw Error("style file " + source_ + ": '" + key + "' " + why);
  }

  void only_keys(const json& object, const std::string& where, std::initializer_list<std::string_view> keys) const {
    if (!object.is_object()) fail(where, "must be an object");
    for (const auto& [key, value] : object.items())
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) fail(where.empty() ? key : where + "." + key, "is not a known key");
  }

  float number(const json& object, const std::string& key, float fallback, float lo, float hi) const {
    if (!object.contains(key)) return fallback;
    const json& v = object[key];
    if (!v.is_number()) fail(key, "must be a number");
    const double d = v.get<double>();
    if (!(d >= lo && d <= hi)) fail(key, "must be within " + std::to_string(lo) + ".." + std::to_string(hi));
    return float(d);
  }

  int integer(const json& object, const std::string& key, int fallback, int lo, int hi) const {
    if (!object.contains(key)) return fallback;
    const json& v = object[key];
    if (!v.is_number_integer()) fail(key, "must be a whole number");
    const long long i = v.get<long long>();
    if (i < lo || i > hi) fail(key, "must be within " + std::to_string(lo) + ".." + std::to_string(hi));
    return int(i);
  }

  std::string text(const json& object, const std::string& key, const std::string& fallback) const {
    if (!object.contains(key)) return fallback;
    if (!object[key].is_string()) fail(key, "must be a string");
    return object[key].get<std::string>();
  }

  template <typename F>
  auto guarded(const std::string& key, F&& parse) const {
    try {
      return parse();
    } catch (const Error& e) {
      if (std::string_view(e.what()).starts_with("style file")) throw;
      fail(key, e.what());
    }
  }

  std::vector<BrushShape> shapes(const json& value) const {
    if (!value.is_array() || value.empty() || value.size() > 64) fail("shapes", "must be a list of 1..64 shape names");
    std::vector<BrushShape> out;
    for (const json& s : value) {
      if (!s.is_string()) fail("shapes", "must hold shape names");
      out.push_back(guarded("shapes", [&] { return brush_shape(s.get<std::string>()); }));
    }
    return out;
  }

  Palette palette(const json& value) const {
    only_keys(value, "palette", {"kind", "shades", "saturation", "tint", "image"});
    Palette p;
    p.kind = guarded("palette.kind", [&] { return palette_kind(text(value, "kind", "natural")); });
    p.shades = integer(value, "shades", 6, 1, 64);
    p.saturation = number(value, "saturation", 1.0f, 0.0f, 4.0f);
    p.tint = guarded("palette.tint", [&] { return parse_hex_colour(text(value, "tint", "#ffffff")); });
    if (p.kind == PaletteKind::Lookup) {
      const std::string image = text(value, "image", "");
      if (image.empty()) fail("palette.image", "is needed by a lookup palette");
      const std::filesystem::path path = std::filesystem::path(image).is_absolute() ? std::filesystem::path(image) : folder_ / image;
      p.ramp = guarded("palette.image", [&] { return ramp_from_image(load_image(path)); });
    }
    return p;
  }

  StrokeOrientation orientation(const json& value) const {
    only_keys(value, "orientation", {"kind", "angle_degrees", "jitter_degrees"});
    static const std::map<std::string, OrientationKind> kinds = {
        {"random", OrientationKind::Random}, {"constant", OrientationKind::Constant}, {"circular", OrientationKind::Circular}, {"gradient", OrientationKind::Gradient}};
    const std::string kind = text(value, "kind", "gradient");
    const auto found = kinds.find(kind);
    if (found == kinds.end()) fail("orientation.kind", "must be random, constant, circular or gradient, not '" + kind + "'");
    return {found->second, number(value, "angle_degrees", 0, -360, 360), number(value, "jitter_degrees", 0, 0, 180)};
  }

  RegionRule region(const json& value) const {
    only_keys(value, "regions[]", {"when", "shapes", "size", "orientation", "opacity", "palette"});
    RegionRule r;
    if (value.contains("when")) {
      const json& when = value["when"];
      only_keys(when, "when", {"luminance", "saturation"});
      auto range = [&](const char* key, float& lo, float& hi) {
        if (!when.contains(key)) return;
        const json& v = when[key];
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) fail(std::string("when.") + key, "must be [min, max]");
        lo = v[0].get<float>(), hi = v[1].get<float>();
        if (!(lo >= 0 && hi <= 1 && lo <= hi)) fail(std::string("when.") + key, "must satisfy 0 <= min <= max <= 1");
      };
      range("luminance", r.luminance_min, r.luminance_max);
      range("saturation", r.saturation_min, r.saturation_max);
    }
    if (value.contains("shapes")) r.shapes = shapes(value["shapes"]);
    r.size = number(value, "size", 1.0f, 0.1f, 10.0f);
    if (value.contains("orientation")) r.orientation = orientation(value["orientation"]);
    if (value.contains("opacity")) r.opacity = number(value, "opacity", 1.0f, 0.0f, 1.0f);
    if (value.contains("palette")) r.palette = palette(value["palette"]);
    return r;
  }

  PaintStyle style(const json& root) const {
    only_keys(root, "", {"name", "description", "brushes", "shapes", "aspect", "coverage", "opacity", "colour_frames", "underpaint", "colour_jitter",
                         "edge_softness", "blend", "wet_edges", "granulation", "glow", "ground", "palette", "orientation", "motion", "regions"});
    PaintStyle s;
    s.name = text(root, "name", source_);
    s.brushes = integer(root, "brushes", s.brushes, 1, 100000);
    if (root.contains("shapes")) s.shapes = shapes(root["shapes"]);
    s.aspect = number(root, "aspect", s.aspect, 0.2f, 12.0f);
    s.coverage = number(root, "coverage", s.coverage, 0.3f, 0.999f);
    s.opacity = number(root, "opacity", s.opacity, 0.0f, 1.0f);
    s.colour_frames = integer(root, "colour_frames", s.colour_frames, 1, 255);
    s.underpaint = number(root, "underpaint", s.underpaint, 0.0f, 1.0f);
    s.colour_jitter = number(root, "colour_jitter", s.colour_jitter, 0.0f, 0.5f);
    s.edge_softness = number(root, "edge_softness", s.edge_softness, 0.0f, 2.0f);
    if (const std::string blend = text(root, "blend", "over"); blend == "glaze")
      s.glaze = true;
    else if (blend != "over")
      fail("blend", "must be over or glaze, not '" + blend + "'");
    s.wet_edges = number(root, "wet_edges", s.wet_edges, 0.0f, 1.0f);
    s.granulation = number(root, "granulation", s.granulation, 0.0f, 1.0f);
    if (root.contains("glow")) {
      const json& g = root["glow"];
      only_keys(g, "glow", {"strength", "radius"});
      s.glow = number(g, "strength", 1.0f, 0.0f, 4.0f);
      s.glow_radius = number(g, "radius", s.glow_radius, 0.005f, 0.25f);
    }
    s.ground = text(root, "ground", "");
    if (!s.ground.empty()) guarded("ground", [&] { return BackdropSpec::parse(s.ground); });
    if (root.contains("palette")) s.palette = palette(root["palette"]);
    if (root.contains("orientation")) s.orientation = orientation(root["orientation"]);
    if (root.contains("motion")) {
      const json& m = root["motion"];
      only_keys(m, "motion", {"max_speed", "jitter", "damping", "time_to_live", "randomise_ttl"});
      s.motion.max_speed = number(m, "max_speed", s.motion.max_speed, 0.0f, 0.2f);
      s.motion.jitter = number(m, "jitter", s.motion.jitter, 0.0f, 0.2f);
      s.motion.damping = number(m, "damping", s.motion.damping, 0.0f, 1.0f);
      s.motion.time_to_live = integer(m, "time_to_live", s.motion.time_to_live, 1, 1000);
      if (m.contains("randomise_ttl")) {
        if (!m["randomise_ttl"].is_boolean()) fail("motion.randomise_ttl", "must be true or false");
        s.motion.randomise_ttl = m["randomise_ttl"].get<bool>();
      }
    }
    if (root.contains("regions")) {
      const json& regions = root["regions"];
      if (!regions.is_array() || regions.size() > 64) fail("regions", "must be a list of at most 64 rules");
      for (const json& r : regions) s.regions.push_back(region(r));
    }
    return s;
  }

 private:
  std::string source_;
  std::filesystem::path folder_;
};

constexpr size_t kMaxStyleFileBytes = 1 << 20;

}  // namespace

bool RegionRule::matches(glm::vec3 rgb) const {
  const float y = luminance(rgb);
  const float maxc = std::max({rgb.r, rgb.g, rgb.b}), minc = std::min({rgb.r, rgb.g, rgb.b});
  const float saturation = maxc > 1e-5f ? (maxc - minc) / maxc : 0.0f;
  return y >= luminance_min && y <= luminance_max && saturation >= saturation_min && saturation <= saturation_max;
}

namespace {

PaintStyle parse_in_folder(const std::string& json_text, const std::string& source, const std::filesystem::path& folder) {
  if (json_text.size() > kMaxStyleFileBytes) throw Error("style file " + source + ": larger than 1 MiB");
  json root;
  try {
    root = json::parse(json_text);
  } catch (const json::exception& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw Error("style file " + source + ": not JSON: " + what);
  }
  return StyleReader(source, folder).style(root);
}

}  // namespace

PaintStyle parse_paint_style(const std::string& json_text, const std::string& source) {
  return parse_in_folder(json_text, source, std::filesystem::current_path());
}

std::vector<std::string> shipped_paint_styles() {
  std::vector<std::string> names;
  for (const auto& [file, text] : painterly_style_files()) names.push_back(std::filesystem::path(file).stem().string());
  return names;
}

PaintStyle load_paint_style(const std::string& name_or_path) {
  const auto& shipped = painterly_style_files();
  if (const auto found = shipped.find(name_or_path + ".json"); found != shipped.end())
    return parse_in_folder(std::string(found->second), name_or_path, std::filesystem::current_path());
  const std::filesystem::path path(name_or_path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::string known;
    for (const std::string& n : shipped_paint_styles()) known += (known.empty() ? "" : ", ") + n;
    throw Error("painting style '" + name_or_path + "' is neither a shipped style (" + known + ") nor a file");
  }
  if (std::filesystem::file_size(path, ec) > kMaxStyleFileBytes) throw Error("style file " + path.string() + ": larger than 1 MiB");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw Error("style file " + path.string() + ": cannot be read");
  return parse_in_folder(text.str(), path.string(), path.parent_path());
}

}  // namespace inkwire
