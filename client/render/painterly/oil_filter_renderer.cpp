#include "client/render/painterly/oil_filter_renderer.hpp"

#include "client/gl/gl.hpp"
#include "client/render/painterly/oil_filter.hpp"

namespace inkwire {

using namespace gl;

OilFilterRenderer::OilFilterRenderer()
    : filtered_(Texture::from_image(Image(1, 1), {.repeat = false, .mipmaps = false, .linear = false})),
      matte_(Texture::from_image(Image(1, 1), {.repeat = false, .mipmaps = false, .linear = true})) {}

std::vector<ParamSpec> OilFilterRenderer::params() {
  return {
      text_param("reference", "default", "the style whose picture is filtered", {"default", "comic", "comic-extended", "hidden-line"}),
      int_param("radius", "5", 1, 64, "window radius: (2r+1)^2 pixels; 5 matches the study's 10x10 window"),
      int_param("levels", "20", 2, 256, "intensity bins"),
  };
}

void OilFilterRenderer::configure(const StyleParams& p) {
  radius_ = p.get_int("radius");
  levels_ = p.get_int("levels");
  capture_.use_renderer(p.get_text("reference"));
}

void OilFilterRenderer::prepare(const SceneObject& object) {
  capture_.prepare(object);
}

void OilFilterRenderer::draw(const FrameState& frame) {
  const Image& reference = capture_.capture(frame);
  if (reference.empty()) return;
  filtered_.update(oil_filter(reference, radius_, levels_));
  matte_.update(reference);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  rect_image_.draw(filtered_, matte_, capture_.rect(), /*premultiplied=*/false, 1.0f);
  glDisable(GL_BLEND);
}

std::map<std::string, double> OilFilterRenderer::counters() const {
  return {{"capture_pixels", capture_.pixels()}, {"radius", double(radius_)}};
}

}  // namespace inkwire
