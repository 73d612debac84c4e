#include "client/render/styles.hpp"

#include "client/render/comic/comic_renderer.hpp"
#include "client/render/default_renderer.hpp"
#include "client/render/hidden_line_renderer.hpp"
#include "client/render/sketch/recursive_sketcher.hpp"
#include "client/render/sketch/textured_sketcher.hpp"
#include "common/error.hpp"

namespace inkwire {

const std::vector<StyleInfo>& styles() {
  static const std::vector<StyleInfo> all = {
      {"default", "smooth-shaded, one light, textured where possible: the speed reference", "#d9dde3",
       &DefaultRenderer::params, [] { return std::make_unique<DefaultRenderer>(); }},
      {"hidden-line", "silhouette, crease and open edges as lines, hidden parts removed, over paper", "paper",
       &HiddenLineRenderer::params, [] { return std::make_unique<HiddenLineRenderer>(); }},
      {"comic", "banded N.L shading from a 1D shade map, thick outline from back faces in wide lines", "paper",
       [] { return ComicRenderer::params(false); }, [] { return std::make_unique<ComicRenderer>(false); }},
      {"comic-extended", "2D shade map over (N.L, R.V) with a moving highlight band; fast CPU face orientation", "paper",
       [] { return ComicRenderer::params(true); }, [] { return std::make_unique<ComicRenderer>(true); }},
      {"sketch-recursive", "silhouettes and creases drawn 1-4 times as wobbling hand-drawn lines that boil at 12 Hz", "paper",
       &RecursiveSketcher::params, [] { return std::make_unique<RecursiveSketcher>(); }},
      {"sketch-pencil", "graphite strokes with paper grain along every outline edge, fading in and out", "paper",
       [] { return TexturedSketcher::params(Medium::Pencil); }, [] { return std::make_unique<TexturedSketcher>(Medium::Pencil); }},
      {"sketch-charcoal", "broad, crumbling charcoal strokes along every outline edge, fading in and out", "paper",
       [] { return TexturedSketcher::params(Medium::Charcoal); }, [] { return std::make_unique<TexturedSketcher>(Medium::Charcoal); }},
      {"sketch-chalk", "dry white chalk strokes on a dark board", "#2e3b35",
       [] { return TexturedSketcher::params(Medium::Chalk); }, [] { return std::make_unique<TexturedSketcher>(Medium::Chalk); }},
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

std::unique_ptr<Renderer> make_renderer(const std::string& name, const std::vector<std::string>& assignments) {
  const StyleInfo& style = find_style(name);
  StyleParams params(style.params());
  for (const std::string& a : assignments) params.set_assignment(a);
  std::unique_ptr<Renderer> renderer = style.create();
  renderer->configure(params);
  return renderer;
}

}  // namespace inkwire
