#include "client/render/styles.hpp"

#include <algorithm>

#include "client/render/comic/comic_renderer.hpp"
#include "client/render/default_renderer.hpp"
#include "client/render/hatching/hatching_renderer.hpp"
#include "client/render/hidden_line_renderer.hpp"
#include "client/render/painterly/oil_filter_renderer.hpp"
#include "client/render/painterly/painterly_renderer.hpp"
#include "client/render/sketch/recursive_sketcher.hpp"
#include "client/render/sketch/segment_sketcher.hpp"
#include "client/render/sketch/textured_sketcher.hpp"
#include "client/render/tween/tween_renderer.hpp"
#include "common/error.hpp"

namespace inkwire {

// The sketchers pick new lines 12 times a second; brushes move a step every frame drawn, and
// 24 steps a second is the pace their motion settings were chosen at.
constexpr double kBoilHz = 12.0, kBrushMotionHz = 24.0;

const std::vector<StyleInfo>& styles() {
  static const std::vector<StyleInfo> all = {
      {.name = "default", .summary = "smooth-shaded, one light, textured where possible: the speed reference", .default_backdrop = "#d9dde3",
       .params = &DefaultRenderer::params, .create = [] { return std::make_unique<DefaultRenderer>(); }},
      {.name = "hidden-line", .summary = "silhouette, crease and open edges as lines, hidden parts removed, over paper", .default_backdrop = "paper",
       .params = &HiddenLineRenderer::params, .create = [] { return std::make_unique<HiddenLineRenderer>(); }},
      {.name = "comic", .summary = "banded N.L shading from a 1D shade map, thick outline from back faces in wide lines", .default_backdrop = "paper",
       .params = [] { return ComicRenderer::params(false); }, .create = [] { return std::make_unique<ComicRenderer>(false); }},
      {.name = "comic-extended", .summary = "2D shade map over (N.L, R.V) with a moving highlight band; fast CPU face orientation", .default_backdrop = "paper",
       .params = [] { return ComicRenderer::params(true); }, .create = [] { return std::make_unique<ComicRenderer>(true); }},
      {.name = "sketch-recursive", .summary = "silhouettes and creases drawn 1-4 times as wobbling hand-drawn lines that boil at 12 Hz", .default_backdrop = "paper",
       .params = &RecursiveSketcher::params, .create = [] { return std::make_unique<RecursiveSketcher>(); },
       .redraw_hz = kBoilHz},
      {.name = "sketch-segments", .summary = "every outline edge drawn with one of a few pre-made sketchy lines, chosen anew 12 times a second", .default_backdrop = "paper",
       .params = &SegmentSketcher::params, .create = [] { return std::make_unique<SegmentSketcher>(); },
       .redraw_hz = kBoilHz},
      {.name = "sketch-pencil", .summary = "graphite strokes with paper grain along every outline edge, fading in and out", .default_backdrop = "paper",
       .params = [] { return TexturedSketcher::params(Medium::Pencil); }, .create = [] { return std::make_unique<TexturedSketcher>(Medium::Pencil); }},
      {.name = "sketch-charcoal", .summary = "broad, crumbling charcoal strokes along every outline edge, fading in and out", .default_backdrop = "paper",
       .params = [] { return TexturedSketcher::params(Medium::Charcoal); }, .create = [] { return std::make_unique<TexturedSketcher>(Medium::Charcoal); }},
      {.name = "sketch-chalk", .summary = "dry white chalk strokes on a dark board", .default_backdrop = "#2e3b35",
       .params = [] { return TexturedSketcher::params(Medium::Chalk); }, .create = [] { return std::make_unique<TexturedSketcher>(Medium::Chalk); }},
      {.name = "hatching", .summary = "screen-space pencil hatching whose density follows the light, crossing in the shadows, with a pencil outline (outline=...; or join one: hatching+sketch-charcoal)", .default_backdrop = "paper",
       .params = &HatchingRenderer::params, .create = [] { return std::make_unique<HatchingRenderer>(); }},
      {.name = "painterly", .summary = "textured brushes that drift over the object, seek it and take their paint from a reference rendering; style files", .default_backdrop = "canvas",
       .params = &PainterlyRenderer::params, .create = [] { return std::make_unique<PainterlyRenderer>(); },
       .redraw_hz = kBrushMotionHz, .in_effect = &painterly_settings_in_effect, .ground = &painterly_ground},
      {.name = "oil-filter", .summary = "the classic oil-paint image filter over a reference rendering: the baseline brushes must beat", .default_backdrop = "canvas",
       .params = &OilFilterRenderer::params, .create = [] { return std::make_unique<OilFilterRenderer>(); }},
      {.name = "tween", .summary = "super-realistic: views synthesised by warping sample images (rendered from the mesh, or photos) along control points", .default_backdrop = "#d9dde3",
       .params = &TweenRenderer::params, .create = [] { return std::make_unique<TweenRenderer>(); }},
  };
  return all;
}

const StyleInfo& find_style(const std::string& name) {
  std::string known;
  for (const StyleInfo& s : styles()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw Error("unknown style '" + name + "' (known: " + known + ")");
}

namespace {

std::vector<std::string> split_parts(const std::string& name) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t plus = name.find('+'); ; plus = name.find('+', start)) {
    parts.push_back(name.substr(start, plus == std::string::npos ? std::string::npos : plus - start));
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  return parts;
}

// Several renderers drawing the same object in turn: e.g. hatching, then outline strokes.
class CompositeRenderer final : public Renderer {
 public:
  CompositeRenderer(std::vector<std::unique_ptr<Renderer>> parts, std::vector<StyleParams> params)
      : parts_(std::move(parts)), params_(std::move(params)) {}
  void configure(const StyleParams& changes) override {
    for (size_t i = 0; i < parts_.size(); ++i) {
      for (const auto& [key, value] : changes.values())
        if (params_[i].has(key)) params_[i].set(key, value);
      parts_[i]->configure(params_[i]);
    }
  }
  void prepare(const SceneObject& object) override {
    for (auto& p : parts_) p->prepare(object);
  }
  void draw(const FrameState& frame) override {
    FrameState part = frame;
    for (auto& p : parts_) {
      p->draw(part);
      // Lines after an opaque surface that laid the depth (hatching, then strokes) skip theirs.
      part.depth_laid = part.depth_laid || p->left_line_depth();
    }
  }
  bool left_line_depth() const override {
    return std::any_of(parts_.begin(), parts_.end(), [](const auto& p) { return p->left_line_depth(); });
  }
  std::map<std::string, double> counters() const override {
    std::map<std::string, double> all;
    for (const auto& p : parts_) all.merge(p->counters());
    return all;
  }

 private:
  std::vector<std::unique_ptr<Renderer>> parts_;
  std::vector<StyleParams> params_;
};

}  // namespace

std::vector<StyleParams> style_params(const std::string& name, const std::vector<std::string>& assignments) {
  const std::vector<std::string> names = split_parts(name);
  std::vector<StyleParams> params;
  for (const std::string& part : names) params.emplace_back(find_style(part).params());
  // Hatching joined with lines of its own choosing ("hatching+sketch-charcoal") takes those as
  // its outline instead of drawing a second one; an explicit outline=... still wins.
  const auto outlines = HatchingRenderer::outline_styles();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == "hatching" &&
        std::any_of(names.begin(), names.end(), [&](const std::string& n) { return std::find(outlines.begin(), outlines.end(), n) != outlines.end(); }))
      params[i].set("outline", "none");
  for (const std::string& a : assignments) {
    const auto [key, value] = split_assignment(a);
    bool used = false;
    for (StyleParams& p : params)
      if (p.has(key)) p.set(key, value), used = true;
    if (!used) params.front().set(key, value);  // throws, naming the known keys
  }
  return params;
}

std::vector<ParamSpec> style_param_specs(const std::string& name) {
  std::vector<ParamSpec> specs;
  for (const std::string& part : split_parts(name))
    for (ParamSpec& p : find_style(part).params())
      if (std::none_of(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == p.name; })) specs.push_back(std::move(p));
  return specs;
}

std::unique_ptr<Renderer> make_renderer(const std::string& name, const std::vector<std::string>& assignments) {
  const std::vector<std::string> names = split_parts(name);
  const std::vector<StyleParams> params = style_params(name, assignments);
  std::vector<std::unique_ptr<Renderer>> parts;
  for (size_t i = 0; i < names.size(); ++i) {
    parts.push_back(find_style(names[i]).create());
    parts.back()->configure(params[i]);
  }
  if (parts.size() == 1) return std::move(parts.front());
  return std::make_unique<CompositeRenderer>(std::move(parts), std::move(params));
}

std::map<std::string, std::string> style_settings_in_effect(const std::string& name, const std::vector<std::string>& assignments) {
  const std::vector<std::string> names = split_parts(name);
  const std::vector<StyleParams> params = style_params(name, assignments);
  std::map<std::string, std::string> values;
  for (size_t i = 0; i < names.size(); ++i) {
    const StyleInfo& info = find_style(names[i]);
    std::map<std::string, std::string> part = info.in_effect ? info.in_effect(params[i]) : params[i].values();
    values.merge(part);  // a name the parts share: the first part's value, as style_param_specs describes it
  }
  return values;
}

double style_redraw_hz(const std::string& name) {
  double hz = 0.0;
  for (const std::string& part : split_parts(name)) hz = std::max(hz, find_style(part).redraw_hz);
  return hz;
}

std::vector<std::string> style_names() {
  std::vector<std::string> names;
  for (const StyleInfo& s : styles()) names.push_back(s.name);
  return names;
}

std::string default_backdrop(const std::string& name, const std::vector<std::string>& assignments) {
  const StyleInfo& first = find_style(split_parts(name).front());
  if (first.ground)
    if (std::string ground = first.ground(style_params(name, assignments).front()); !ground.empty()) return ground;
  return first.default_backdrop;
}

}  // namespace inkwire
